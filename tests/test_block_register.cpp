// Registers 1, 2, 9, 10–12 of Fig. 1 alone: a register captures its input on the
// rising edge of its write strobe and at no other time (spec §3 "Decision (done)":
// register writes use the rising edge of their strobe).
#include <gtest/gtest.h>

#include "specular/datapath/register.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockRegister, CapturesOnlyOnTheRisingEdgeOfItsStrobe) {
  bus_signal d{"d"};
  wire load{"load"};
  bus_signal q{"q"};
  Register reg9{"reg9"};
  reg9.d(d);
  reg9.load(load);
  reg9.q(q);

  settle();
  EXPECT_EQ(q.read(), 0) << "power-on value";
  d.write(42);
  settle();
  EXPECT_EQ(q.read(), 0) << "no strobe, no capture";
  load.write(true);
  settle();
  EXPECT_EQ(q.read(), 42) << "rising edge captures";
  d.write(7);
  settle();
  EXPECT_EQ(q.read(), 42) << "a high strobe is not transparent";
  load.write(false);
  settle();
  EXPECT_EQ(q.read(), 42) << "the falling edge does not capture";
  d.write(-5);
  settle();
  EXPECT_EQ(q.read(), 42);
  load.write(true);
  settle();
  EXPECT_EQ(q.read(), -5) << "signed codes pass unchanged";
  load.write(false);
  d.write(code_t{1} << 40);
  settle();
  load.write(true);
  settle();
  EXPECT_EQ(q.read(), code_t{1} << 40) << "wide codes pass unchanged";
}

TEST(BlockRegister, HoldsItsPowerOnValueUntilTheFirstWrite) {
  bus_signal d{"d", 11};
  wire load{"load"};
  bus_signal q{"q"};
  Register reg2{"reg2", 1};
  reg2.d(d);
  reg2.load(load);
  reg2.q(q);
  settle();
  EXPECT_EQ(q.read(), 1);
  load.write(true);
  settle();
  EXPECT_EQ(q.read(), 11);
}

}  // namespace
}  // namespace specular
