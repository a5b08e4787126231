// The scene the example virtual platform renders: one sphere per panel, lit by one
// white-ish light, seen from +z; panel p uses the specular exponent n[p].
//
// Everything the CPU computes before it drives the IP (normals, the quantised cos λ =
// N·H, the diffuse base colour) and the way it adds the IP's result to a pixel lives
// here, header-only, so that a test can render the same picture with Core::run on the
// same quantised inputs and compare byte for byte.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace specular {
namespace vp {

struct Vec {
  double x, y, z;
};

inline double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec normalised(const Vec& v) {
  const double length = std::sqrt(dot(v, v));
  return {v.x / length, v.y / length, v.z / length};
}

/// Directions towards the light and the viewer; H is the half-way vector.
inline Vec light_direction() { return normalised({-0.45, 0.55, 0.70}); }
inline Vec view_direction() { return {0.0, 0.0, 1.0}; }
inline Vec half_vector() {
  const Vec l = light_direction(), v = view_direction();
  return normalised({l.x + v.x, l.y + v.y, l.z + v.z});
}

/// Specular exponents of the panels, left to right, and the light's R, G, B (0..255).
inline constexpr std::array<unsigned, 4> panel_n{1, 10, 100, 1000};
inline constexpr std::array<std::uint32_t, 3> light_rgb{255, 244, 224};
inline constexpr std::array<std::uint8_t, 3> background{12, 12, 18};

/// A COS word that is no cos λ (above 1.0): marks a pixel outside the sphere in the
/// CPU's cos buffer.
inline constexpr std::uint32_t outside = 0xFFFFFFFFu;

/// The unit normal of the sphere at pixel (x, y) of a size×size panel (pixel centres,
/// y down, radius 0.45·size); false outside the sphere.
inline bool normal_at(int x, int y, int size, Vec& normal) {
  const double radius = 0.45 * size;
  const double u = (x + 0.5 - 0.5 * size) / radius;
  const double v = (0.5 * size - (y + 0.5)) / radius;
  const double r2 = u * u + v * v;
  if (r2 >= 1.0) return false;
  normal = {u, v, std::sqrt(1.0 - r2)};
  return true;
}

/// cos λ = max(0, N·H) as the IP's COS code (U1.16: 65536 = 1.0), rounded.
inline std::uint32_t cos_code(const Vec& normal) {
  const double c = std::clamp(dot(normal, half_vector()), 0.0, 1.0);
  return static_cast<std::uint32_t>(std::lround(c * 65536.0));
}

/// The CPU's own diffuse shading: albedo × (ambient 0.15 + 0.85·max(0, N·L)).
inline std::array<std::uint8_t, 3> base_colour(const Vec& normal) {
  constexpr double albedo[3] = {70, 90, 140};
  const double shade = 0.15 + 0.85 * std::max(0.0, dot(normal, light_direction()));
  std::array<std::uint8_t, 3> rgb{};
  for (int ch = 0; ch < 3; ++ch) rgb[ch] = static_cast<std::uint8_t>(std::lround(albedo[ch] * shade));
  return rgb;
}

/// A pixel channel plus the IP's output for it (pins 24–26, S18.13): rounded to an
/// integer, negative (the `literal` policy) taken as 0, the sum saturated at 255.
inline std::uint8_t add_specular(std::uint8_t base, std::int32_t out_code) {
  const std::int64_t specular = (static_cast<std::int64_t>(out_code) + 4096) >> 13;
  return static_cast<std::uint8_t>(std::clamp<std::int64_t>(base + std::max<std::int64_t>(specular, 0), 0, 255));
}

}  // namespace vp
}  // namespace specular
