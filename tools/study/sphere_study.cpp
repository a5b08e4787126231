#include "sphere_study.h"

#include <cmath>
#include <cstdio>

#include "csv.h"
#include "lobes.h"
#include "specular/core.h"
#include "specular/reference.h"

namespace specular {
namespace study {

namespace {
std::array<double, 3> normalised(std::array<double, 3> v) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (double& c : v) c /= length;
  return v;
}
double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
}  // namespace

std::vector<SpherePixel> sphere_pixels(const SphereScene& scene) {
  const std::array<double, 3> light = normalised(scene.light);
  const std::array<double, 3> half = normalised({light[0], light[1], light[2] + 1.0});  // (L + V)/|L + V|
  std::vector<SpherePixel> pixels;
  for (int row = 0; row < scene.size; ++row)
    for (int column = 0; column < scene.size; ++column) {
      const double x = (column + 0.5) / scene.size * 2.0 - 1.0;
      const double y = 1.0 - (row + 0.5) / scene.size * 2.0;
      const double r2 = x * x + y * y;
      if (r2 > 1.0) continue;
      const std::array<double, 3> normal = {x, y, std::sqrt(1.0 - r2)};
      SpherePixel p;
      p.x = column;
      p.y = row;
      p.n_dot_l = dot(normal, light);
      p.cos_lambda = std::min(1.0, std::max(0.0, dot(normal, half)));
      pixels.push_back(p);
    }
  return pixels;
}

void run_sphere_study(const StudyOptions& options) {
  SphereScene scene;
  if (options.quick) scene.size = 40;
  const std::vector<SpherePixel> pixels = sphere_pixels(scene);
  const std::array<Normalisation, 3> policies = {Normalisation::none, Normalisation::patent,
                                                 Normalisation::energy};
  std::vector<Core> cores;
  for (Normalisation policy : policies) cores.emplace_back(Config{Widths{}, policy, Saturation::clamp});
  // Issue 14: s·A under the two minimax constants, and device-energy under minimax.
  std::vector<Core> minimax;
  minimax.emplace_back(Config{Widths{}, Normalisation::none, Saturation::clamp, Constants::minimax_half});
  minimax.emplace_back(Config{Widths{}, Normalisation::none, Saturation::clamp, Constants::minimax});
  minimax.emplace_back(Config{Widths{}, Normalisation::device_energy, Saturation::clamp, Constants::minimax});
  const Formats& formats = cores.front().formats();

  for (unsigned n : StudyOptions::sphere_n_values()) {
    CsvWriter csv(options.out_dir + "/sphere_n" + std::to_string(n) + ".csv",
                  {"x", "y", "size", "n", "cos", "n_dot_l", "exact", "exact_energy", "device_none",
                   "device_patent", "device_energy", "schlick", "us5739820", "device_minimax_half",
                   "device_minimax", "device_minimax_device_energy"});
    for (const SpherePixel& p : pixels) {
      const double cos = p.cos_lambda;
      csv.cell(static_cast<long long>(p.x)).cell(static_cast<long long>(p.y));
      csv.cell(static_cast<long long>(scene.size)).cell(static_cast<long long>(n));
      csv.cell(cos).cell(p.n_dot_l);
      if (p.n_dot_l <= 0) {  // facing away from the light: no specular term for any lobe
        for (int column = 0; column < 10; ++column) csv.cell(0.0);
        csv.end_row();
        continue;
      }
      csv.cell(reference::exact_lobe(cos, n));
      csv.cell(reference::k(n, Normalisation::energy) * reference::exact_lobe(cos, n));
      Operands in;
      in.n = n;
      in.cos = quantise_cos(formats, cos);
      for (const Core& core : cores) csv.cell(formats.norm.to_real(core.run(in).norm39));
      csv.cell(schlick(cos, n)).cell(us5739820(cos, n));
      for (const Core& core : minimax) csv.cell(formats.norm.to_real(core.run(in).norm39));
      csv.end_row();
    }
    std::fprintf(stderr, "  sphere n = %u: %zu pixels -> %s\n", n, pixels.size(),
                 csv.path().c_str());
  }
}

}  // namespace study
}  // namespace specular
