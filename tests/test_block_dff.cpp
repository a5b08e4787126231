// D flip-flops 41, 42, 43 of Fig. 2 alone: D is taken on the rising edge of C;
// asynchronous active-low R and S act at once, and R beats S when both are low.
#include <gtest/gtest.h>

#include "specular/control/d_flip_flop.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

class Dff {
 public:
  wire d{"d"}, c{"c"}, s_n{"s_n", true}, r_n{"r_n", true}, q{"q"}, q_n{"q_n"};
  DFlipFlop dff{"dff41"};
  Dff() {
    dff.d(d);
    dff.c(c);
    dff.s_n(s_n);
    dff.r_n(r_n);
    dff.q(q);
    dff.q_n(q_n);
  }
  /// Q, after checking that /Q is its complement.
  bool state() const {
    EXPECT_NE(q.read(), q_n.read()) << "Q and /Q must be complements";
    return q.read();
  }
};

TEST(BlockDff, ClocksOnTheRisingEdgeAndResetBeatsSet) {
  Dff f;
  settle();
  EXPECT_FALSE(f.state()) << "power-on state";

  f.d.write(true);
  settle();
  EXPECT_FALSE(f.state()) << "D alone does nothing";
  f.c.write(true);
  settle();
  EXPECT_TRUE(f.state()) << "rising C takes D = 1";
  f.d.write(false);
  settle();
  EXPECT_TRUE(f.state()) << "C high is not transparent";
  f.c.write(false);
  settle();
  EXPECT_TRUE(f.state()) << "falling C does nothing";
  f.c.write(true);
  settle();
  EXPECT_FALSE(f.state()) << "rising C takes D = 0";
  f.c.write(false);
  settle();

  // Asynchronous set and reset, no clock.
  f.s_n.write(false);
  settle();
  EXPECT_TRUE(f.state()) << "S low sets at once";
  f.s_n.write(true);
  settle();
  EXPECT_TRUE(f.state()) << "releasing S keeps the state";
  f.r_n.write(false);
  settle();
  EXPECT_FALSE(f.state()) << "R low resets at once";
  f.s_n.write(false);
  settle();
  EXPECT_FALSE(f.state()) << "R beats S when both are low";
  f.r_n.write(true);
  settle();
  EXPECT_TRUE(f.state()) << "S still low sets once R is released";
  f.s_n.write(true);
  settle();

  // R held low blocks the clock.
  f.r_n.write(false);
  f.d.write(true);
  settle();
  f.c.write(true);
  settle();
  EXPECT_FALSE(f.state()) << "a clock edge during reset is ignored";
  f.c.write(false);
  f.r_n.write(true);
  settle();
  EXPECT_FALSE(f.state()) << "releasing R does not clock D in";
  f.c.write(true);
  settle();
  EXPECT_TRUE(f.state());
}

}  // namespace
}  // namespace specular
