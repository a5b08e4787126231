// A plain C++ program (int main, no SystemC kernel) that computes the device's bits with
// specular::Core, as a test generator or a firmware unit test would. It links
// SpecularUnit::core only (issue 29): no libsystemc, so no sc_main is needed.
// scripts/verify/consumer_check.sh builds it against the installed package and checks that it
// needs no SystemC library; the project builds it as specular_core_example.
//
// Each result is checked against the patent's formula computed here in double, from
// docs/spec.md and not from the library: A = 1 − ½·log2(1 − n·log2 cos λ), clamped at
// 0, K(n) = 2π/(n + 2), pins 24–26 = K·A·I in S18.13; within the documented bound
// 2^-10·max(1, K)·I + 1 LSB (docs/accuracy.md). Exits 0 when all are within it.
#include <cmath>
#include <cstdint>
#include <iostream>

#include <specular/core.h>

namespace {

/// The patent's formula on the quantised input, in double (default Config: patent
/// normalisation and constants, clamp, COS U1.16; log2 0 taken as log2 of the smallest
/// code, −16).
double expected_out(std::int64_t cos_code, unsigned n, double intensity) {
  const double pi = std::acos(-1.0);
  const double log2_cos = cos_code == 0 ? -16.0 : std::log2(static_cast<double>(cos_code) / 65536.0);
  const double a = std::fmax(0.0, 1.0 - 0.5 * std::log2(1.0 - n * log2_cos));
  return 2.0 * pi / (n + 2.0) * a * intensity;
}

}  // namespace

int main() {
  const specular::Core core;  // default Config: the patent's device
  const std::int64_t cos_codes[] = {0, 1, 1000, 20000, 45000, 60000, 64500, 65000, 65535, 65536};
  const unsigned exponents[] = {1, 2, 5, 40, 100, 1000};
  const std::int64_t intensities[][3] = {{255, 200, 100}, {0, 1, 128}, {255, 255, 255}};
  int checked = 0, outside = 0;
  for (const std::int64_t cos : cos_codes)
    for (const unsigned n : exponents)
      for (const auto& rgb : intensities) {
        const specular::Result r = core.run({cos, n, {rgb[0], rgb[1], rgb[2]}});
        const double k = 2.0 * std::acos(-1.0) / (n + 2.0);
        for (int ch = 0; ch < 3; ++ch) {
          const double got = static_cast<double>(r.out[ch]) / 8192.0;  // S18.13
          const double want = expected_out(cos, n, static_cast<double>(rgb[ch]));
          const double bound = std::ldexp(1.0, -10) * std::fmax(1.0, k) * rgb[ch] + 1.0 / 8192.0;
          ++checked;
          if (!(std::fabs(got - want) <= bound)) {
            ++outside;
            std::cout << "cos " << cos << " n " << n << " channel " << ch << ": Core " << got
                      << ", formula " << want << ", bound " << bound << "\n";
          }
        }
      }
  std::cout << "consumer_core: " << checked - outside << "/" << checked
            << " outputs of Core within the documented bound of the double formula: "
            << (outside == 0 ? "PASS" : "FAIL") << std::endl;
  return outside == 0 ? 0 : 1;
}
