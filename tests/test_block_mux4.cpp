// Multiplexer 4 of Fig. 1 alone: select 36 = 0 passes register 2 (n), select 36 = 1
// passes pin 19 (the wired constant ½), both on multiplier 6's operand bus.
#include <gtest/gtest.h>

#include <cmath>

#include "specular/datapath/multiplexer4.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockMux4, SelectsNThenTheConstantHalf) {
  const Formats f;
  bus_signal reg2{"reg2"}, h19{"h19"}, operand{"operand"};
  wire select36{"select36"};
  Multiplexer4 mux4{"mux4", f};
  mux4.reg2(reg2);
  mux4.h19(h19);
  mux4.select36(select36);
  mux4.operand(operand);

  h19.write(std::llround(std::ldexp(0.5, f.mux4.frac_bits)));  // ½, the patent's pin 19
  for (code_t n : {1, 2, 3, 500, 999, 1000, 1023}) {
    reg2.write(n);
    select36.write(false);
    settle();
    EXPECT_EQ(f.mux4.to_real(operand.read()), static_cast<double>(n));
    select36.write(true);
    settle();
    EXPECT_EQ(f.mux4.to_real(operand.read()), 0.5) << "n = " << n;
  }
}

}  // namespace
}  // namespace specular
