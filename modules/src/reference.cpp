#include "specular/reference.h"

#include <algorithm>
#include <cmath>

namespace specular {
namespace reference {

namespace {
constexpr double two_pi = 6.283185307179586476925286766559;
}

double log2_cos(double cos_q, int cos_frac_bits) {
  return std::log2(std::max(cos_q, std::ldexp(1.0, -cos_frac_bits)));
}

double approx(double cos_q, unsigned n, Saturation saturation, int cos_frac_bits) {
  const double x = n * log2_cos(cos_q, cos_frac_bits);
  const double a = 1.0 - 0.5 * std::log2(1.0 - x);
  return saturation == Saturation::clamp ? std::max(a, 0.0) : a;
}

double k(unsigned n, Normalisation policy) {
  switch (policy) {
    case Normalisation::patent: return two_pi / (n + 2.0);
    case Normalisation::energy: return (n + 2.0) / two_pi;
    case Normalisation::none: return 1.0;
  }
  return 1.0;
}

double exact_lobe(double cos_q, unsigned n) { return std::pow(cos_q, static_cast<double>(n)); }

Figures evaluate(double cos_q, unsigned n, const std::array<double, 3>& rgb,
                 Normalisation normalisation, Saturation saturation, int cos_frac_bits) {
  Figures f;
  f.cos_q = cos_q;
  f.approx_ref = approx(cos_q, n, saturation, cos_frac_bits);
  const double kn = k(n, normalisation);
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
