// The minimax search for the constants on pins 19 and 20 (issue 14).
//
// With a on pin 20, h on pin 19 and ROM 38's words scaled by s, the device computes
// s·max(0, a − h·log2(a + x)) for x = −n·log2 cos λ ≥ 0; the peak is made exact,
// s = 1/(a − h·log2 a). The search finds, among the values the buses can hold — a on
// pin 20's 2^−22 grid (register 9's fraction bits), h on pin 19's 2^−F grid — the pair
// with the smallest largest error max_x |s·A − 2^−x|. It is a branch and bound whose
// lower bounds come from two monotonicities proved in docs/study.md, so its answer
// is the global optimum of the grid, not a local one.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace specular {
namespace study {

/// The largest errors of one (a, h): above (s·A > 2^−x) and below (s·A < 2^−x,
/// including the clamp's tail 2^−x0 past the zero crossing x0 = 2^(a/h) − a).
struct ConstantsError {
  double above = 0;
  double below = 0;
  double worst() const { return above > below ? above : below; }
};

/// Exact (to double precision) for real a, h: the error's extrema are where
/// (a + x)·2^−x = h/(D·ln²2), D = a − h·log2 a, at most one on each side of the
/// maximum of (a + x)·2^−x, found by bisection; plus the zero crossing.
ConstantsError constants_error(double a, double h);

/// The search's answer for one pin-19 grid.
struct ConstantsResult {
  int h_frac_bits = 0;       ///< F: pin 19 holds h = h_code·2^−F
  std::int64_t h_code = 0;
  int a_frac_bits = 22;      ///< pin 20 holds a = a_code·2^−22
  std::int64_t a_code = 0;
  double a = 0, h = 0, s = 0;
  ConstantsError error;      ///< at the optimum
  long boxes = 0;            ///< boxes the branch and bound visited
  long evaluations = 0;      ///< constants_error calls
};

/// The search domain: every positive a pin 20 holds (register 9's S14.22: a < 2^14)
/// with a ≥ h/ln2, and h ∈ (0, 15/8]. Below h/ln2 every point is worse than the
/// patent's 0.125 (docs/study.md); up to 15/8, a − h·log2 a > 0 for every a > 0, so
/// every point has an exact peak and the monotonicities hold.
constexpr double search_h_max = 1.875;
constexpr int search_a_frac_bits = 22;
constexpr int search_a_int_bits = 14;

/// The best (a, h) with h on `h_frac_bits` fraction bits (h free in the domain), or,
/// when `h_fixed_code` ≥ 0, the best a with h = h_fixed_code·2^−F. Deterministic: ties
/// go to the smaller h code, then the smaller a code.
ConstantsResult search_constants(int h_frac_bits, std::int64_t h_fixed_code = -1);

/// The trade-off table: the patent's point, minimax-half, and minimax for F = 1 … max_f,
/// with the F the data choose (the fewest bits within 1 % of the best any F reaches).
struct ConstantsTable {
  std::vector<std::pair<std::string, ConstantsResult>> rows;  ///< "patent", "minimax-half", "minimax"
  int chosen_f = 0;
  double best = 0;
};
ConstantsTable constants_table(int max_f);
/// constants_search.csv: search, F, extra_mul6_bits, h_code, h, a_code, a, s, max_error,
/// error_above, error_below, boxes, evaluations.
void write_constants_csv(const ConstantsTable& table, const std::string& path);

}  // namespace study
}  // namespace specular
