// specular_bench: how the repetitions of one figure are summarised and how a target
// is judged (issue 12). A shared machine makes one run's figure a draw from a noisy
// distribution, so the bench reports the median and the spread (min..max) of several
// interleaved repetitions, and a target is "met" only when the whole spread meets it.
// Pure functions, no SystemC: tests/test_bench_smoke.cpp checks them on made-up figures.
#pragma once

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace specular_bench {

/// One figure over its repetitions.
struct Spread {
  double median = 0;
  double min = 0;
  double max = 0;
  std::size_t count = 0;  ///< how many repetitions gave the figure
};

/// Median (the mean of the two middle values for an even count), min and max.
inline Spread spread_of(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("spread_of: no values");
  std::sort(values.begin(), values.end());
  Spread s;
  s.count = values.size();
  s.min = values.front();
  s.max = values.back();
  const std::size_t mid = values.size() / 2;
  s.median = values.size() % 2 == 1 ? values[mid] : (values[mid - 1] + values[mid]) / 2;
  return s;
}

enum class Verdict {
  met,           ///< every repetition is on the right side of the bound
  not_met,       ///< every repetition is on the wrong side
  within_noise,  ///< the spread straddles the bound: this machine cannot tell
};

inline const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::met: return "met";
    case Verdict::not_met: return "not met";
    case Verdict::within_noise: return "within noise";
  }
  return "?";
}

/// A performance target: figure `figure` must be at least (or at most) `bound`.
struct Target {
  std::string figure;  ///< the figure judged, e.g. core_vs_pow; the verdict line is target_<figure>
  bool at_least;       ///< true: figure >= bound; false: figure <= bound
  double bound;
  std::string what;    ///< what the figure measures, in words
};

/// The verdict on `s` against a target: met when min..max all meet the bound, not met
/// when none does, within noise otherwise. A value equal to the bound meets it.
inline Verdict judge(const Spread& s, bool at_least, double bound) {
  const double worst = at_least ? s.min : s.max;
  const double best = at_least ? s.max : s.min;
  const auto meets = [&](double v) { return at_least ? v >= bound : v <= bound; };
  if (meets(worst)) return Verdict::met;
  if (!meets(best)) return Verdict::not_met;
  return Verdict::within_noise;
}

/// How many targets got each verdict.
struct VerdictCount {
  int met = 0, not_met = 0, within_noise = 0;
  int total() const { return met + not_met + within_noise; }
  void add(Verdict v) {
    if (v == Verdict::met) ++met;
    else if (v == Verdict::not_met) ++not_met;
    else ++within_noise;
  }
};

}  // namespace specular_bench
