// ROM 38 of Fig. 1 alone: K(n) addressed by register 2, within half a word LSB of
// 2π/(n+2) (patent), (n+2)/(2π) (energy, ≈ 159.5 at n = 1000) or 1 (none).
#include <gtest/gtest.h>

#include <cmath>

#include "specular/datapath/rom38.h"

namespace specular {
namespace {

constexpr double two_pi = 6.283185307179586476925286766559;

TEST(BlockRom38, HoldsKOfNUnderEveryPolicy) {
  const Formats f;
  const arith::Rom38Table patent_table(f, Normalisation::patent);
  const arith::Rom38Table energy_table(f, Normalisation::energy);
  const arith::Rom38Table none_table(f, Normalisation::none);
  bus_signal reg2{"reg2"}, k_patent{"k_patent"}, k_energy{"k_energy"}, k_none{"k_none"};
  Rom38 rom38_patent{"rom38_patent", patent_table};
  Rom38 rom38_energy{"rom38_energy", energy_table};
  Rom38 rom38_none{"rom38_none", none_table};
  rom38_patent.reg2(reg2);
  rom38_energy.reg2(reg2);
  rom38_none.reg2(reg2);
  rom38_patent.k(k_patent);
  rom38_energy.k(k_energy);
  rom38_none.k(k_none);

  const double half_lsb = f.rom38.lsb() / 2;
  for (code_t n = 1; n <= 1000; ++n) {
    reg2.write(n);
    sc_core::sc_start(1, sc_core::SC_NS);
    ASSERT_NEAR(f.rom38.to_real(k_patent.read()), two_pi / (n + 2.0), half_lsb) << "n = " << n;
    ASSERT_NEAR(f.rom38.to_real(k_energy.read()), (n + 2.0) / two_pi, half_lsb) << "n = " << n;
    ASSERT_EQ(f.rom38.to_real(k_none.read()), 1.0) << "n = " << n;
  }
  // The last address read was n = 1000: energy's largest coefficient, ≈ 159.5.
  EXPECT_NEAR(f.rom38.to_real(k_energy.read()), 159.47, 0.005);
  EXPECT_NEAR(f.rom38.to_real(k_patent.read()), 0.006270, 1e-5);
}

}  // namespace
}  // namespace specular
