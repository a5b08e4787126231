// Spheres lit by one white light, shaded with each lobe: what a user sees of the
// approximation and of each normalisation policy.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "study_options.h"

namespace specular {
namespace study {

/// The view looks down −z (V = +z); the light comes from the upper left.
struct SphereScene {
  std::array<double, 3> light{-0.5, 0.6, 0.62};  ///< direction to the light (normalised on use)
  int size = 200;                                ///< image width = height in pixels
};

/// One pixel inside the sphere's outline.
struct SpherePixel {
  int x = 0, y = 0;         ///< column, row (row 0 at the top)
  double cos_lambda = 0;    ///< N·H, in [0, 1]
  double n_dot_l = 0;       ///< ≤ 0: the surface faces away from the light, no highlight
};

/// The pixels of the sphere (N from the orthographic view), with N·H and N·L.
std::vector<SpherePixel> sphere_pixels(const SphereScene& scene);

/// Writes sphere_n<n>.csv for n = 1, 10, 100, 1000 into options.out_dir: per pixel,
/// the specular term under each lobe (white light of intensity 1): exact cos^n, exact
/// × (n+2)/(2π), the device (K·A from multiplier 39) under each policy, Schlick,
/// US 5739820; 0 where N·L ≤ 0. The device's values come from Core at cos λ rounded to register 1.
void run_sphere_study(const StudyOptions& options);

}  // namespace study
}  // namespace specular
