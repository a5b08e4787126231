// Multiplier 39 of Fig. 1 alone: register 9 × ROM 38 = K·A, within half an LSB of
// the exact product; register 9's pass-1 value (up to ~16 000) saturates silently.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "specular/datapath/multiplier39.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockMul39, KTimesAIsRoundedToTheNormFormat) {
  const Formats f;
  bus_signal reg9{"reg9"}, k{"k"}, norm{"norm"};
  Multiplier39 mul39{"mul39", f};
  mul39.reg9(reg9);
  mul39.k(k);
  mul39.norm(norm);

  auto code = [](double v, int frac) { return static_cast<code_t>(std::llround(std::ldexp(v, frac))); };
  std::mt19937 random(39);
  for (int i = 0; i < 500; ++i) {
    const double a = std::uniform_real_distribution<double>(-6.2, 1.0)(random);  // literal reaches −6.1
    const double kn = std::uniform_real_distribution<double>(0.006, 160.0)(random);
    const code_t a_code = code(a, f.reg9.frac_bits);
    const code_t k_code = code(kn, f.rom38.frac_bits);
    reg9.write(a_code);
    k.write(k_code);
    settle();
    const double exact = f.reg9.to_real(a_code) * f.rom38.to_real(k_code);
    if (std::fabs(exact) >= 1023.0) continue;  // beyond the S10.20 bus, see below
    EXPECT_NEAR(f.norm.to_real(norm.read()), exact, f.norm.lsb() / 2) << a << " × " << kn;
  }

  // Between the passes: register 9 = 16 001 × K = 159.5 saturates at the largest code.
  reg9.write(code(16001.0, f.reg9.frac_bits));
  k.write(code(159.47, f.rom38.frac_bits));
  settle();
  EXPECT_EQ(norm.read(), f.norm.max_code());
  EXPECT_NEAR(f.norm.to_real(norm.read()), 1024.0, 1e-5);
  reg9.write(code(-200.0, f.reg9.frac_bits));
  settle();
  EXPECT_EQ(norm.read(), f.norm.min_code());
  EXPECT_EQ(f.norm.to_real(norm.read()), -1024.0);
}

}  // namespace
}  // namespace specular
