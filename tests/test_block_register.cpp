// Registers 1, 2, 9, 10–12 of Fig. 1 alone: a register captures its input on the
// rising edge of its write strobe and at no other time (spec §3 "Decision (done)":
// register writes use the rising edge of their strobe).
#include <gtest/gtest.h>

#include <string>

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

/// Each register of Fig. 1 with the extreme codes of the bus it holds (design note's
/// formats, written out here): register 1 cos λ U1.16 (1.0 = 2^16), register 2 n
/// U10.0 (1000), register 9 S14.22 (−2^36 … 2^36 − 1), registers 10–12 U8.0 (255).
struct RegisterCase {
  const char* name;
  code_t low, high;
};

class EachRegister : public ::testing::TestWithParam<RegisterCase> {};

TEST_P(EachRegister, CapturesItsBusExtremesOnItsStrobeOnly) {
  const RegisterCase& c = GetParam();
  bus_signal d{"d"};
  wire load{"load"};
  bus_signal q{"q"};
  Register reg{c.name};
  reg.d(d);
  reg.load(load);
  reg.q(q);
  EXPECT_EQ(std::string(reg.basename()), c.name);
  for (const code_t value : {c.high, c.low, c.high}) {
    d.write(value);
    settle();
    EXPECT_NE(q.read(), value) << "captured before its strobe rose";
    load.write(true);
    settle();
    EXPECT_EQ(q.read(), value);
    load.write(false);
    d.write(value == c.high ? c.low : c.high);
    settle();
    EXPECT_EQ(q.read(), value) << "held after the strobe fell";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Fig1, EachRegister,
    ::testing::Values(RegisterCase{"reg1", 1, 65536}, RegisterCase{"reg2", 1, 1000},
                      RegisterCase{"reg9", -(code_t{1} << 36), (code_t{1} << 36) - 1},
                      RegisterCase{"reg10", 1, 255}, RegisterCase{"reg11", 1, 255},
                      RegisterCase{"reg12", 1, 255}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace specular
