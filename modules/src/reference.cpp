#include "specular/reference.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "specular/constants.h"

namespace specular {
namespace reference {

namespace {
constexpr double two_pi = 6.283185307179586476925286766559;
}

double log2_cos(double cos_q, int cos_frac_bits) {
  return std::log2(std::max(cos_q, std::ldexp(1.0, -cos_frac_bits)));
}

double approx(double cos_q, unsigned n, Saturation saturation, int cos_frac_bits,
              Constants constants) {
  const ConstantValues& c = constant_values(constants);
  const double x = n * log2_cos(cos_q, cos_frac_bits);
  const double a = c.a() - c.h() * std::log2(c.a() - x);
  return saturation == Saturation::clamp ? std::max(a, 0.0) : a;
}

double code_interval_integral(long long code, int cos_frac_bits) {
  const double lsb = std::ldexp(1.0, -cos_frac_bits);
  const double lo = std::max(0.0, (static_cast<double>(code) - 0.5) * lsb);
  const double hi = std::min(1.0, (static_cast<double>(code) + 0.5) * lsb);
  return 0.5 * two_pi * (hi * hi - lo * lo);
}

namespace {
/// I(n) of the double formula, clamped, over every cos code; cached (the testbench
/// asks for it once per operation, and each costs 2^F logarithms).
double formula_integral(unsigned n, Constants constants, int cos_frac_bits) {
  static std::mutex mutex;
  static std::map<std::tuple<unsigned, int, int>, double> cache;
  const auto key = std::make_tuple(n, static_cast<int>(constants), cos_frac_bits);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = cache.find(key);
    if (found != cache.end()) return found->second;
  }
  double sum = 0;
  for (long long c = 1LL << cos_frac_bits; c >= 0; --c) {
    const double a = approx(std::ldexp(static_cast<double>(c), -cos_frac_bits), n, Saturation::clamp,
                            cos_frac_bits, constants);
    if (a <= 0) break;  // the formula falls with cos: nothing below its zero crossing
    sum += a * code_interval_integral(c, cos_frac_bits);
  }
  const std::lock_guard<std::mutex> lock(mutex);
  cache.emplace(key, sum);
  return sum;
}
}  // namespace

double k(unsigned n, Normalisation policy, Constants constants, int cos_frac_bits) {
  const double s = constant_values(constants).s();
  switch (policy) {
    case Normalisation::patent: return s * two_pi / (n + 2.0);
    case Normalisation::energy: return s * (n + 2.0) / two_pi;
    case Normalisation::none: return s;
    case Normalisation::device_energy: return 1.0 / formula_integral(n, constants, cos_frac_bits);
  }
  return s;
}

double exact_lobe(double cos_q, unsigned n) { return std::pow(cos_q, static_cast<double>(n)); }

Figures evaluate(double cos_q, unsigned n, const std::array<double, 3>& rgb,
                 Normalisation normalisation, Saturation saturation, int cos_frac_bits,
                 Constants constants) {
  Figures f;
  f.cos_q = cos_q;
  f.approx_ref = approx(cos_q, n, saturation, cos_frac_bits, constants);
  const double kn = k(n, normalisation, constants, cos_frac_bits);
  f.norm_ref = kn * f.approx_ref;
  f.norm_exact = kn * exact_lobe(cos_q, n);
  for (int ch = 0; ch < 3; ++ch) f.out_ref[ch] = f.norm_ref * rgb[ch];
  return f;
}

double approx_tolerance() { return std::ldexp(1.0, -10); }
double norm_tolerance(double kn) { return std::ldexp(1.0, -10) * std::max(1.0, kn); }
double out_tolerance(double kn, double intensity, double out_lsb) {
  return norm_tolerance(kn) * intensity + out_lsb;
}

}  // namespace reference
}  // namespace specular
