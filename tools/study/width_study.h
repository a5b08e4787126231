// The fixed-point widths, justified by data: the device's error against the double
// formula, and the ROM sizes, as ROM 5's address and word widths, register 9's
// fraction bits and ROM 38's fraction bits vary (one at a time, and ROM 5's address ×
// word on a grid). Every device here is a Core built with other Widths.
#pragma once

#include <string>
#include <vector>

#include "specular/format.h"
#include "study_options.h"

namespace specular {
namespace study {

/// One device configuration of the exploration.
struct WidthCase {
  std::string sweep;  ///< "rom5_addr", "rom5_word", "reg9_frac", "rom38_frac" or "grid"
  Widths widths;
};

/// The configurations visited (full or quick).
std::vector<WidthCase> width_cases(bool quick);

/// What one configuration achieves, over every n visited and every cos code.
struct WidthResult {
  WidthCase config;
  long rom5_bits = 0;
  long rom38_bits = 0;
  double max_err_vs_formula = 0;  ///< |A_device − A_formula| (both clamped), register 9
  unsigned worst_n = 0;
  double worst_cos = 0;
  double max_err_vs_exact = 0;    ///< |A_device − cos^n|
  double max_norm_err = 0;        ///< |K·A (multiplier 39) − K·A_formula| / max(1, K), patent K
};

/// Measures every case over every n in `ns`; `workers` threads; `quiet`: no progress
/// line (parallel_for).
std::vector<WidthResult> explore_widths(const std::vector<WidthCase>& cases,
                                        const std::vector<unsigned>& ns, unsigned workers,
                                        bool quiet = false);

/// Writes widths.csv (one row per case) and widths_near_one.csv (n = 1000, the top of
/// the cos range, for ROM 5 address widths around cos_frac_bits − 1) into
/// options.out_dir; returns the results.
std::vector<WidthResult> run_width_study(const StudyOptions& options);

}  // namespace study
}  // namespace specular
