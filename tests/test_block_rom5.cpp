// ROM 5 of Fig. 1 alone: the log2 unit both passes share. Pass 1 reads cos λ codes
// (every one fits ROM 5's address: half a word LSB from std::log2), pass 2 reads
// register 9 (1 … ~16 000: within the mantissa-truncation bound), and log2 0 is −F
// (spec §4, Decision "log2 0").
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "specular/datapath/rom5.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockRom5, Log2OfCosCodesAndOfRegister9Values) {
  const Formats f;
  const arith::Rom5Table table(f);
  bus_signal address{"address"}, log2{"log2"};
  Rom5 rom5{"rom5", table};
  rom5.address(address);
  rom5.log2(log2);

  const int W = f.widths.rom5_word_bits;
  const double word_half_lsb = std::ldexp(0.5, -W);
  const double mantissa_bound = std::log2(1.0 + std::ldexp(1.0, -f.widths.rom5_addr_bits));
  auto bus_code = [&](double value) {
    return static_cast<code_t>(std::llround(std::ldexp(value, f.reg9.frac_bits)));
  };

  // log2 0 := log2 of the smallest cos code = −16, exactly.
  address.write(0);
  settle();
  EXPECT_EQ(f.log2.to_real(log2.read()), -16.0);

  // Pass 1: cos codes, including the smallest and the last ones below 1.0, and 1.0.
  std::mt19937 random(59965);
  std::vector<code_t> codes = {1, 2, 3, 255, 256, 32767, 32768, 46341, 65534, 65535, 65536};
  for (int i = 0; i < 500; ++i) codes.push_back(std::uniform_int_distribution<code_t>(1, 65536)(random));
  for (code_t c : codes) {
    const double cos = std::ldexp(static_cast<double>(c), -16);
    address.write(bus_code(cos));
    settle();
    EXPECT_NEAR(f.log2.to_real(log2.read()), std::log2(cos), word_half_lsb + 1e-15) << "cos code " << c;
  }
  address.write(bus_code(1.0));
  settle();
  EXPECT_EQ(f.log2.to_real(log2.read()), 0.0) << "log2 1 = 0 exactly";

  // Pass 2: register 9 after pass 1, 1 − n·log2 cos λ ∈ [1, 16 001].
  std::vector<double> values = {1.0, 1.5, 2.0, 3.999, 4.0, 17.0, 1000.25, 8192.0, 16001.0};
  for (int i = 0; i < 500; ++i) values.push_back(std::uniform_real_distribution<double>(1.0, 16001.0)(random));
  for (double v : values) {
    const code_t code = bus_code(v);
    address.write(code);
    settle();
    EXPECT_NEAR(f.log2.to_real(log2.read()), std::log2(f.reg9.to_real(code)),
                mantissa_bound + word_half_lsb) << "register 9 = " << v;
  }
  // Powers of two have a zero mantissa: exact.
  address.write(bus_code(1024.0));
  settle();
  EXPECT_EQ(f.log2.to_real(log2.read()), 10.0);
}

}  // namespace
}  // namespace specular
