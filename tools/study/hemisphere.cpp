#include "hemisphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace specular {
namespace study {

namespace {

constexpr double pi = 3.14159265358979323846264338327950288;

// Gauss–Kronrod 7/15 nodes on [−1, 1] (QUADPACK's qk15): Kronrod nodes, Kronrod
// weights, and the weights of the embedded 7-point Gauss rule (odd Kronrod nodes).
constexpr std::array<double, 8> xgk = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr std::array<double, 8> wgk = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> wg = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Estimate {
  double value;
  double error;
};

Estimate kronrod15(const std::function<double(double)>& g, double a, double b) {
  const double centre = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  const double fc = g(centre);
  double kronrod = fc * wgk[7];
  double gauss = fc * wg[3];
  for (int j = 0; j < 7; ++j) {
    const double dx = half * xgk[j];
    const double sum = g(centre - dx) + g(centre + dx);
    kronrod += wgk[j] * sum;
    if (j % 2 == 1) gauss += wg[j / 2] * sum;
  }
  return {kronrod * half, std::abs((kronrod - gauss) * half)};
}

double adaptive(const std::function<double(double)>& g, double a, double b, double tolerance,
                int depth) {
  const Estimate whole = kronrod15(g, a, b);
  if (whole.error <= tolerance || depth >= 60) return whole.value;
  const double middle = 0.5 * (a + b);
  return adaptive(g, a, middle, 0.5 * tolerance, depth + 1) +
         adaptive(g, middle, b, 0.5 * tolerance, depth + 1);
}

}  // namespace

double hemisphere_integral(const std::function<double(double)>& f, std::vector<double> breaks,
                           double tolerance) {
  breaks.erase(std::remove_if(breaks.begin(), breaks.end(),
                              [](double t) { return !(t > 0.0 && t < 1.0); }),
               breaks.end());
  breaks.push_back(0.0);
  breaks.push_back(1.0);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  const auto integrand = [&f](double t) { return f(t) * t; };
  double sum = 0.0;
  const double piece_tolerance = tolerance / (breaks.size() - 1);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    sum += adaptive(integrand, breaks[i], breaks[i + 1], piece_tolerance, 0);
  return 2.0 * pi * sum;
}

double hemisphere_integral_of_codes(const std::vector<double>& values, int cos_frac_bits) {
  const std::size_t codes = (std::size_t{1} << cos_frac_bits) + 1;
  if (values.size() != codes)
    throw std::invalid_argument("hemisphere_integral_of_codes: " + std::to_string(values.size()) +
                                " values given, one per cos code 0 .. 2^" +
                                std::to_string(cos_frac_bits) + " (" + std::to_string(codes) +
                                ") expected");
  const double lsb = std::ldexp(1.0, -cos_frac_bits);
  double sum = 0.0;
  for (std::size_t c = 0; c < codes; ++c) {
    const double a = std::max(0.0, (static_cast<double>(c) - 0.5) * lsb);
    const double b = std::min(1.0, (static_cast<double>(c) + 0.5) * lsb);
    sum += values[c] * (b - a) * (b + a);  // ∫_a^b 2t dt = b² − a²
  }
  return pi * sum;
}

}  // namespace study
}  // namespace specular
