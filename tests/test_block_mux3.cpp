// Multiplexer 3 of Fig. 1 alone: select 36 = 0 passes register 1 (cos λ) aligned to
// register 9's format, select 36 = 1 passes register 9 (spec §2 Decision: in0 = 1, in1 = 9).
#include <gtest/gtest.h>

#include <cmath>

#include "specular/datapath/multiplexer3.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockMux3, SelectsRegister1ThenRegister9OnOneBus) {
  const Formats f;
  bus_signal reg1{"reg1"}, reg9{"reg9"}, address{"address"};
  wire select36{"select36"};
  Multiplexer3 mux3{"mux3", f};
  mux3.reg1(reg1);
  mux3.reg9(reg9);
  mux3.select36(select36);
  mux3.address(address);

  const code_t reg9_value = static_cast<code_t>(std::ldexp(1234.5, f.reg9.frac_bits));
  reg9.write(reg9_value);
  for (double cos : {0.0, 1.0 / 65536, 0.5, 0.70710678, 65535.0 / 65536, 1.0}) {
    const code_t code = static_cast<code_t>(std::llround(std::ldexp(cos, 16)));
    reg1.write(code);
    select36.write(false);
    settle();
    // The same real number, now on register 9's bus.
    EXPECT_EQ(f.reg9.to_real(address.read()), f.cos.to_real(code)) << cos;
    select36.write(true);
    settle();
    EXPECT_EQ(address.read(), reg9_value) << cos;
  }
  // Register 9 changing while selected shows through; register 1 changing does not.
  reg9.write(-3);
  reg1.write(77);
  settle();
  EXPECT_EQ(address.read(), -3);
}

}  // namespace
}  // namespace specular
