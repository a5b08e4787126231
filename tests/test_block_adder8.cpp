// Combinational adder 8 of Fig. 1 alone: pin 20 (1.0) + inverter 7's output
// (NOT product) + carry-in 34 = 1 − product; under `clamp` a negative sum is 0,
// under `literal` it stays (spec, Decision "negative results").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "specular/datapath/adder8.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockAdder8, OneMinusProductClampedOrLiteral) {
  const Formats f;
  bus_signal a20{"a20"}, inverted{"inverted"}, clamped{"clamped"}, literal{"literal"};
  wire carry34{"carry34", true};
  Adder8 adder8_clamp{"adder8_clamp", f, Saturation::clamp};
  Adder8 adder8_literal{"adder8_literal", f, Saturation::literal};
  for (Adder8* a : {&adder8_clamp, &adder8_literal}) {
    a->a20(a20);
    a->inverted(inverted);
    a->carry34(carry34);
  }
  adder8_clamp.sum(clamped);
  adder8_literal.sum(literal);
  a20.write(static_cast<code_t>(std::ldexp(1.0, f.reg9.frac_bits)));  // 1.0, pin 20

  std::mt19937 random(8);
  std::vector<double> products = {0.0, 1.0, 2.0, -1.0, 0.5, -16000.0, 6.5, 13.99, -1e-6};
  for (int i = 0; i < 300; ++i) products.push_back(std::uniform_real_distribution<double>(-16000.0, 0.0)(random));
  for (int i = 0; i < 300; ++i) products.push_back(std::uniform_real_distribution<double>(0.0, 8.0)(random));
  for (double p : products) {
    const code_t p_code = static_cast<code_t>(std::llround(std::ldexp(p, f.reg9.frac_bits)));
    inverted.write(-p_code - 1);  // what inverter 7 puts on the bus: NOT product
    settle();
    const double want = 1.0 - f.reg9.to_real(p_code);  // exact: one bus, no rounding
    EXPECT_EQ(f.reg9.to_real(literal.read()), want) << "product " << p;
    EXPECT_EQ(f.reg9.to_real(clamped.read()), std::max(want, 0.0)) << "product " << p;
  }
  // Without the carry-in the adder computes 1 − product − 1 LSB (one's complement).
  carry34.write(false);
  inverted.write(-1);  // NOT 0
  settle();
  EXPECT_EQ(f.reg9.to_real(literal.read()), 1.0 - f.reg9.lsb());
}

}  // namespace
}  // namespace specular
