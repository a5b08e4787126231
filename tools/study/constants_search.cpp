#include "constants_search.h"

#include "csv.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>

namespace specular {
namespace study {

namespace {
constexpr double ln2 = 0.693147180559945309417232121458176568;

/// x with f(x) = target for f monotone on [lo, hi] (increasing when `rising`).
template <class F>
double bisect(F f, double lo, double hi, double target, bool rising) {
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    if ((f(mid) < target) == rising) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}
}  // namespace

ConstantsError constants_error(double a, double h) {
  if (!(a > 0 && h > 0)) throw std::invalid_argument("constants_error: a and h must be positive");
  const double d = a - h * std::log2(a);  // s = 1/d: the peak made exact
  if (!(d > 0)) throw std::invalid_argument("constants_error: a − h·log2 a must be positive");
  const auto error = [&](double x) { return (a - h * std::log2(a + x)) / d - std::exp2(-x); };
  const auto phi = [&](double x) { return (a + x) * std::exp2(-x); };

  ConstantsError r;
  // Zero crossing of a − h·log2(a + x): past it the device gives 0 and the error is
  // −2^−x, largest in magnitude at x0. Beyond 2^−1100 nothing is representable.
  const double ratio = a / h;
  const double x0 = ratio > 1000 ? std::numeric_limits<double>::infinity() : std::exp2(ratio) - a;
  const double end = std::min(x0, 1100.0);
  r.below = std::exp2(-end);
  // error'(x) = 0  ⇔  φ(x) = (a + x)·2^−x = c. φ rises up to x_m = 1/ln2 − a and falls
  // after it, so there is at most one root on each side.
  const double c = h / (d * ln2 * ln2);
  const double xm = 1.0 / ln2 - a;
  const auto take = [&](double x) {
    const double e = error(x);
    r.above = std::max(r.above, e);
    r.below = std::max(r.below, -e);
  };
  if (xm > 0) {
    const double hi = std::min(xm, end);
    if (phi(0) <= c && c <= phi(hi)) take(bisect(phi, 0, hi, c, true));
  }
  const double lo = std::max(0.0, xm);
  if (lo < end && phi(end) <= c && c <= phi(lo)) take(bisect(phi, lo, end, c, false));
  return r;
}

namespace {

struct Box {
  double bound;  ///< no point of the box has a smaller largest error
  std::int64_t h_lo, h_hi, a_lo, a_hi;
};
struct Later {  // priority_queue: smallest bound first, ties by the smaller codes
  bool operator()(const Box& x, const Box& y) const {
    if (x.bound != y.bound) return x.bound > y.bound;
    if (x.h_lo != y.h_lo) return x.h_lo > y.h_lo;
    return x.a_lo > y.a_lo;
  }
};

class Search {
 public:
  explicit Search(int f) : f_(f) {}

  double a_of(std::int64_t code) const { return std::ldexp(static_cast<double>(code), -search_a_frac_bits); }
  double h_of(std::int64_t code) const { return std::ldexp(static_cast<double>(code), -f_); }
  /// Smallest a code in the domain for an h code: a ≥ h/ln2.
  std::int64_t a_min(std::int64_t h_code) const {
    return static_cast<std::int64_t>(std::ceil(std::ldexp(h_of(h_code), search_a_frac_bits) / ln2));
  }
  ConstantsError eval(std::int64_t a, std::int64_t h) {
    ++evaluations;
    return constants_error(a_of(a), h_of(h));
  }
  void consider(std::int64_t a, std::int64_t h) {
    if (a < a_min(h)) return;
    const double w = eval(a, h).worst();
    if (w < best || (w == best && (h < best_h || (h == best_h && a < best_a)))) {
      best = w;
      best_a = a;
      best_h = h;
    }
  }
  /// Lower bound over a box's points in the domain. g = s·A is nonincreasing in h
  /// and, for a ≥ h/ln2, nondecreasing in a, at every x (docs/study.md). So the error
  /// below is smallest at (a_hi, h_lo) and the error above at (a_lo, h_hi) — the
  /// latter only when the whole box lies where a ≥ h/ln2.
  void push(Box b) {
    b.a_lo = std::max(b.a_lo, a_min(b.h_lo));
    if (b.a_lo > b.a_hi) return;
    b.bound = eval(b.a_hi, b.h_lo).below;
    if (b.a_lo >= a_min(b.h_hi)) b.bound = std::max(b.bound, eval(b.a_lo, b.h_hi).above);
    if (b.bound > best) return;
    queue.push(b);
  }

  int f_;
  double best = std::numeric_limits<double>::infinity();
  std::int64_t best_a = -1, best_h = -1;
  long evaluations = 0, boxes = 0;
  std::priority_queue<Box, std::vector<Box>, Later> queue;
};

}  // namespace

ConstantsResult search_constants(int h_frac_bits, std::int64_t h_fixed_code) {
  if (h_frac_bits < 1 || h_frac_bits > 24)
    throw std::invalid_argument("pin 19 fraction bits F = " + std::to_string(h_frac_bits) +
                                " is outside the allowed range [1, 24]");
  Search s(h_frac_bits);
  const std::int64_t h_top = static_cast<std::int64_t>(std::floor(std::ldexp(search_h_max, h_frac_bits)));
  if (h_fixed_code == 0 || h_fixed_code > h_top)
    throw std::invalid_argument("fixed h code " + std::to_string(h_fixed_code) +
                                " is outside the allowed range [1, " + std::to_string(h_top) + "]");
  const std::int64_t h_lo = h_fixed_code > 0 ? h_fixed_code : 1;
  const std::int64_t h_hi = h_fixed_code > 0 ? h_fixed_code : h_top;
  const std::int64_t a_hi = (std::int64_t{1} << (search_a_int_bits + search_a_frac_bits)) - 1;

  s.push({0, h_lo, h_hi, 0, a_hi});
  while (!s.queue.empty()) {
    const Box b = s.queue.top();
    s.queue.pop();
    if (b.bound > s.best) break;  // every box left is worse than the best point
    ++s.boxes;
    if (b.a_lo == b.a_hi && b.h_lo == b.h_hi) {
      s.consider(b.a_lo, b.h_lo);
      continue;
    }
    s.consider(b.a_lo + (b.a_hi - b.a_lo) / 2, b.h_lo + (b.h_hi - b.h_lo) / 2);
    // Split the side that is longer in real units.
    const double a_span = s.a_of(b.a_hi - b.a_lo), h_span = s.h_of(b.h_hi - b.h_lo);
    if (b.h_lo != b.h_hi && (h_span >= a_span || b.a_lo == b.a_hi)) {
      const std::int64_t mid = b.h_lo + (b.h_hi - b.h_lo) / 2;
      s.push({0, b.h_lo, mid, b.a_lo, b.a_hi});
      s.push({0, mid + 1, b.h_hi, b.a_lo, b.a_hi});
    } else {
      const std::int64_t mid = b.a_lo + (b.a_hi - b.a_lo) / 2;
      s.push({0, b.h_lo, b.h_hi, b.a_lo, mid});
      s.push({0, b.h_lo, b.h_hi, mid + 1, b.a_hi});
    }
  }
  if (s.best_a < 0) throw std::logic_error("constants search found no point in its domain");

  ConstantsResult r;
  r.h_frac_bits = h_frac_bits;
  r.h_code = s.best_h;
  r.a_code = s.best_a;
  r.a = s.a_of(r.a_code);
  r.h = s.h_of(r.h_code);
  r.s = 1.0 / (r.a - r.h * std::log2(r.a));
  r.error = constants_error(r.a, r.h);
  r.boxes = s.boxes;
  r.evaluations = s.evaluations;
  return r;
}

ConstantsTable constants_table(int max_f) {
  ConstantsTable t;
  ConstantsResult patent;
  patent.h_frac_bits = 1, patent.h_code = 1, patent.a_code = std::int64_t{1} << search_a_frac_bits;
  patent.a = 1, patent.h = 0.5, patent.s = 1, patent.error = constants_error(1, 0.5);
  t.rows.emplace_back("patent", patent);
  t.rows.emplace_back("minimax-half", search_constants(1, 1));
  for (int f = 1; f <= max_f; ++f) t.rows.emplace_back("minimax", search_constants(f));
  t.best = t.rows.back().second.error.worst();
  for (const auto& row : t.rows) t.best = std::min(t.best, row.second.error.worst());
  for (const auto& row : t.rows)
    if (row.first == "minimax" && t.chosen_f == 0 && row.second.error.worst() <= 1.01 * t.best)
      t.chosen_f = row.second.h_frac_bits;
  return t;
}

void write_constants_csv(const ConstantsTable& table, const std::string& path) {
  CsvWriter csv(path, {"search", "F", "extra_mul6_bits", "h_code", "h", "a_code", "a", "s",
                       "max_error", "error_above", "error_below", "boxes", "evaluations"});
  for (const auto& [name, r] : table.rows) {
    csv.cell(name).cell(static_cast<long long>(r.h_frac_bits))
        .cell(static_cast<long long>(r.h_frac_bits - 1)).cell(static_cast<long long>(r.h_code))
        .cell(r.h).cell(static_cast<long long>(r.a_code)).cell(r.a).cell(r.s)
        .cell(r.error.worst()).cell(r.error.above).cell(r.error.below)
        .cell(static_cast<long long>(r.boxes)).cell(static_cast<long long>(r.evaluations));
    csv.end_row();
  }
}

}  // namespace study
}  // namespace specular
