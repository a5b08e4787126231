// Inverter block 7 of Fig. 1 alone: bitwise NOT within register 9's width, i.e. in
// two's complement ~x = −x − 1 (with carry-in 34 adder 8 then subtracts).
#include <gtest/gtest.h>

#include <random>

#include "specular/datapath/inverter7.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockInv7, InvertsEveryBitWithinTheBusWidth) {
  const Formats f;
  bus_signal product{"product"}, inverted{"inverted"};
  Inverter7 inv7{"inv7", f};
  inv7.product(product);
  inv7.inverted(inverted);

  std::mt19937_64 random(7);
  std::vector<code_t> values = {0, -1, 1, f.reg9.max_code(), f.reg9.min_code(),
                                static_cast<code_t>(std::ldexp(-16000.0, 22)),
                                static_cast<code_t>(std::ldexp(7.25, 22))};
  for (int i = 0; i < 200; ++i)
    values.push_back(std::uniform_int_distribution<code_t>(f.reg9.min_code(), f.reg9.max_code())(random));
  for (code_t x : values) {
    product.write(x);
    settle();
    EXPECT_EQ(inverted.read(), -x - 1) << x;
    EXPECT_GE(inverted.read(), f.reg9.min_code());
    EXPECT_LE(inverted.read(), f.reg9.max_code());
  }
  // All ones and all zeros across the 37-bit bus swap.
  product.write(0);
  settle();
  EXPECT_EQ(inverted.read(), -1);
  product.write(-1);
  settle();
  EXPECT_EQ(inverted.read(), 0);
}

}  // namespace
}  // namespace specular
