// How close each method comes to the exact cos^n λ: error curves for a few n, the
// maximum error for every n, and error maps over (λ, n).
//
// Every method is evaluated at the cos value register 1 holds (cos λ rounded to the
// U1.16 code), and compared with the exact lobe at that same value: the study
// measures the approximations, not the resolution of pin 17 (whose own effect on
// cos^n is up to n·2^−17, i.e. 0.0076 at n = 1000).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "specular/core.h"
#include "study_options.h"

namespace specular {
namespace study {

/// The approximations of cos^n the study compares.
enum class Method {
  device_clamp,     ///< the device, register 9 after pass 2, negative results saturated at 0
  device_literal,   ///< the device keeping negative results
  formula_clamp,    ///< 1 − ½·log2(1 − n·log2 t) in double, clamped at 0 (reference::approx)
  formula_literal,  ///< the same, unclamped
  schlick,          ///< t/(n − n·t + t)
  us5739820,        ///< max(0, 1 − n·(1 − t)/4)^4
  device_minimax_half,  ///< the device under constants minimax-half: s·A (multiplier 39, K = 1)
  device_minimax,       ///< the device under constants minimax: s·A (multiplier 39, K = 1)
};
constexpr std::size_t method_count = 8;
constexpr std::array<Method, method_count> all_methods = {
    Method::device_clamp, Method::device_literal, Method::formula_clamp,
    Method::formula_literal, Method::schlick, Method::us5739820,
    Method::device_minimax_half, Method::device_minimax};
const char* method_name(Method method);

/// Every method's value, and the exact lobe, at every cos code for one n.
struct LobeTables {
  unsigned n = 0;
  std::vector<double> cos;    ///< index = cos code; the real value register 1 holds
  std::vector<double> exact;  ///< cos^n
  std::array<std::vector<double>, method_count> values;
  const std::vector<double>& of(Method method) const {
    return values[static_cast<std::size_t>(method)];
  }
};

/// The largest |f − g| over all codes, and the cos where it occurs (the lowest such).
struct MaxError {
  double value = 0;
  double at_cos = 0;
};
MaxError max_abs_difference(const std::vector<double>& f, const std::vector<double>& g,
                            const std::vector<double>& cos);

/// Builds LobeTables; the device's values come from Cores: clamp and literal under the
/// patent's constants, and multiplier 39 (normalisation none) under the two minimax ones.
class LobeEvaluator {
 public:
  explicit LobeEvaluator(const Widths& widths = Widths{});
  LobeTables tables(unsigned n) const;
  const Core& device(Saturation saturation) const {
    return saturation == Saturation::clamp ? clamp_ : literal_;
  }

 private:
  Core clamp_;
  Core literal_;
  Core minimax_half_;
  Core minimax_;
};

/// The smallest cos at which the device's literal result is ≥ 0, with every smaller
/// code negative: the device's zero crossing (the formula's is 2^(−3/n)).
double device_zero_crossing(const LobeTables& tables);

/// Over all n visited: the largest error of each method, and at which n and cos.
struct ErrorSummary {
  struct Worst {
    double value = 0;
    unsigned n = 0;
    double at_cos = 0;
  };
  std::array<Worst, method_count> worst{};
  Worst device_vs_formula;  ///< the fixed-point error: device (clamp) − formula (clamp)
};

/// Writes error_curves.csv, max_error_by_n.csv and heatmap_<name>.csv into
/// options.out_dir; returns the summary for the console.
ErrorSummary run_error_study(const StudyOptions& options);

}  // namespace study
}  // namespace specular
