// The accuracy sweep behind issue 2 item 7: the Core against the double reference
// over every n in 1..1000 and a set of cos codes (all of them in the long test, a
// sample in the quick one). Shared by test_arith_accuracy.cpp and
// test_long_exhaustive.cpp so that both hold the device to the same bounds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/reference.h"
#include "operation_shard.h"

namespace specular {
namespace testing_support {

/// Every cos code 0 .. 1.0 in steps of `step`, plus the edges a sample must not miss:
/// 0, the smallest codes, the last codes below 1.0, and 1.0 itself.
inline std::vector<code_t> cos_codes(const Formats& f, code_t step) {
  std::vector<code_t> codes;
  for (code_t c = 0; c <= f.cos.one(); c += step) codes.push_back(c);
  for (code_t c : {code_t{0}, code_t{1}, code_t{2}, code_t{3}}) codes.push_back(c);
  for (code_t c = f.cos.one() - 8; c <= f.cos.one(); ++c) codes.push_back(c);
  std::sort(codes.begin(), codes.end());
  codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
  return codes;
}

/// A maximum error and where it happened.
struct Worst {
  double error = 0.0;
  unsigned n = 0;
  code_t cos = 0;
  void update(double e, unsigned at_n, code_t at_cos) {
    if (e > error) {
      error = e;
      n = at_n;
      cos = at_cos;
    }
  }
};

struct SweepFigures {
  long evaluations = 0;
  long approx_misses = 0;  ///< |approx − approx_ref| > 2^-10
  long norm_misses = 0;    ///< |norm − norm_ref| > 2^-10·max(1, K)
  long out_misses = 0;     ///< |out − out_ref| > 2^-10·max(1, K)·I + 1 LSB
  long pass1_misses = 0;   ///< register 9 after pass 1 off 1 − n·log2 cos λ by more than rounding
  Worst approx;            ///< |approx − approx_ref|
  Worst norm_scaled;       ///< |norm − norm_ref| / max(1, K)
  Worst norm;              ///< |norm − norm_ref|
  Worst norm_exact;        ///< |norm − K·cos_q^n|
  Worst out;               ///< |out − out_ref| over the three channels, in units of R, G, B
  Worst out_share;         ///< |out − out_ref| / its bound (1 = at the bound)
  Worst pass1;             ///< |reg9 pass 1 − (a − n·log2 cos_q)|
  Worst lobe_exact;        ///< |s·norm/K − cos_q^n|: the device's own s·A against cos^n
                           ///< (under normalisation none exactly |multiplier 39 − cos_q^n|)
  std::string first_miss;  ///< the first miss, described
};

/// How far pass 1 may be from 1 − n·log2 cos λ: n times ROM 5's error on a cos code
/// (half a word LSB, plus the mantissa truncation when a cos code has more significant
/// bits than ROM 5's address) plus half an LSB of multiplier 6's rounding.
inline double pass1_tolerance(const Formats& f, unsigned n) {
  const Widths& w = f.widths;
  double rom5 = std::ldexp(0.5, -w.rom5_word_bits);
  if (w.cos_frac_bits - 1 > w.rom5_addr_bits) rom5 += std::log2(1.0 + std::ldexp(1.0, -w.rom5_addr_bits));
  return n * rom5 + std::ldexp(0.5, -w.reg9_frac_bits) + 1e-12 * n;
}

/// Runs the Core on every n in 1..1000 of `shard` (all of them by default) × `codes`,
/// intensities {I_max, I_max/2, 1}.
inline SweepFigures sweep(const Config& config, const std::vector<code_t>& codes,
                          const OperationShard& shard = {}) {
  const Core core(config);
  const Formats& f = core.formats();
  const int F = f.cos.frac_bits;
  const std::array<code_t, 3> rgb = {f.rgb.max_code(), (f.rgb.max_code() + 1) / 2, 1};
  SweepFigures s;
  auto miss = [&s](long& counter, const char* what, unsigned n, code_t c, double got, double want) {
    if (counter++ == 0 && s.first_miss.empty()) {
      std::ostringstream m;
      m.precision(10);
      m << what << " at n=" << n << " cos code=" << c << ": got " << got << ", reference " << want;
      s.first_miss = m.str();
    }
  };
  for (unsigned n = n_min; n <= n_max; ++n) {
    if (!shard.covers(n)) continue;
    const double kn = reference::k(n, config.normalisation, config.constants, F);
    const double s_scale = constant_values(config.constants).s();
    const double a = constant_values(config.constants).a();
    const double norm_tol = reference::norm_tolerance(kn);
    const double p1_tol = pass1_tolerance(f, n);
    for (code_t c : codes) {
      Operands in;
      in.cos = c;
      in.n = n;
      in.rgb = rgb;
      const Result r = core.run(in);
      const double cos_q = f.cos.to_real(c);
      const double approx_ref = reference::approx(cos_q, n, config.saturation, F, config.constants);
      const double norm_ref = kn * approx_ref;
      const double pass1_ref = a - n * reference::log2_cos(cos_q, F);

      const double approx = f.reg9.to_real(r.reg9_pass2);
      const double norm = f.norm.to_real(r.norm39);
      const double pass1 = f.reg9.to_real(r.reg9_pass1);

      const double e_approx = std::fabs(approx - approx_ref);
      const double e_norm = std::fabs(norm - norm_ref);
      const double e_pass1 = std::fabs(pass1 - pass1_ref);
      s.approx.update(e_approx, n, c);
      s.norm.update(e_norm, n, c);
      s.norm_scaled.update(e_norm / std::max(1.0, kn), n, c);
      s.norm_exact.update(std::fabs(norm - kn * reference::exact_lobe(cos_q, n)), n, c);
      s.pass1.update(e_pass1, n, c);
      s.lobe_exact.update(std::fabs(s_scale * norm / kn - reference::exact_lobe(cos_q, n)), n, c);
      if (!(e_approx <= reference::approx_tolerance()))
        miss(s.approx_misses, "approx", n, c, approx, approx_ref);
      if (!(e_norm <= norm_tol)) miss(s.norm_misses, "norm", n, c, norm, norm_ref);
      if (!(e_pass1 <= p1_tol)) miss(s.pass1_misses, "register 9 pass 1", n, c, pass1, pass1_ref);
      for (int ch = 0; ch < 3; ++ch) {
        const double intensity = static_cast<double>(rgb[ch]);
        const double out = f.out.to_real(r.out[ch]);
        const double out_ref = norm_ref * intensity;
        const double out_bound = reference::out_tolerance(kn, intensity, f.out.lsb());
        s.out.update(std::fabs(out - out_ref), n, c);
        s.out_share.update(std::fabs(out - out_ref) / out_bound, n, c);
        if (!(std::fabs(out - out_ref) <= out_bound))
          miss(s.out_misses, "out", n, c, out, out_ref);
      }
      ++s.evaluations;
    }
  }
  return s;
}

/// "1.2e-05 (2^-16.3)"
inline std::string with_power_of_two(double e) {
  char text[64];
  if (e > 0)
    std::snprintf(text, sizeof text, "%.3g (2^%.1f)", e, std::log2(e));
  else
    std::snprintf(text, sizeof text, "0");
  return text;
}

inline std::string where(const Formats& f, const Worst& w) {
  char text[80];
  std::snprintf(text, sizeof text, "n=%u cos=%lld (%.7f)", w.n, static_cast<long long>(w.cos),
                f.cos.to_real(w.cos));
  return text;
}

/// One line per policy combination, for the README's accuracy table.
inline std::string summary(const Config& config, const SweepFigures& s) {
  const Formats f(config.widths);
  std::ostringstream line;
  line << "constants=" << to_string(config.constants) << " policy=" << to_string(config.normalisation)
       << " saturation=" << to_string(config.saturation) << " evaluations=" << s.evaluations
       << " max|approx-ref|=" << with_power_of_two(s.approx.error) << " at " << where(f, s.approx)
       << "; max|norm-ref|/max(1,K)=" << with_power_of_two(s.norm_scaled.error) << " at "
       << where(f, s.norm_scaled) << "; max|norm-ref|=" << with_power_of_two(s.norm.error)
       << " at " << where(f, s.norm) << "; max|norm-exact|=" << with_power_of_two(s.norm_exact.error)
       << " at " << where(f, s.norm_exact) << "; max|out-out_ref|=" << with_power_of_two(s.out.error)
       << " at " << where(f, s.out) << "; max|out-out_ref|/bound=" << s.out_share.error
       << " at " << where(f, s.out_share) << "; max|pass1-ref|=" << with_power_of_two(s.pass1.error)
       << " at " << where(f, s.pass1) << "; max|s*A-exact|=" << s.lobe_exact.error << " at "
       << where(f, s.lobe_exact);
  return line.str();
}

}  // namespace testing_support
}  // namespace specular
