// The gates of Fig. 2 alone (AND 40, inverter 44, NAND 47, NANDs 45 and 46): every
// row of every truth table, each gate a separate instance named after Fig. 2.
#include <gtest/gtest.h>

#include "specular/control/gates.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockGates, TruthTables) {
  wire a{"a"}, b{"b"}, c{"c"};
  wire inv44_y{"inv44_y"}, and40_y{"and40_y"}, nand47_y{"nand47_y"}, nand45_y{"nand45_y"},
      nand46_y{"nand46_y"};
  NotGate inv44{"inv44"};
  AndGate2 and40{"and40"};
  NandGate2 nand47{"nand47"};
  NandGate3 nand45{"nand45"};
  NandGate3 nand46{"nand46"};
  inv44.a(a);
  inv44.y(inv44_y);
  and40.a(a);
  and40.b(b);
  and40.y(and40_y);
  nand47.a(a);
  nand47.b(b);
  nand47.y(nand47_y);
  nand45.a(a);
  nand45.b(b);
  nand45.c(c);
  nand45.y(nand45_y);
  nand46.a(c);  // other input order than nand45: each input pin of the instance matters
  nand46.b(a);
  nand46.c(b);
  nand46.y(nand46_y);

  // Rows in Gray-code order, so that every step changes one input (no stale values hide).
  const int gray[8] = {0, 1, 3, 2, 6, 7, 5, 4};
  for (int row : gray) {
    const bool va = row & 4, vb = row & 2, vc = row & 1;
    a.write(va);
    b.write(vb);
    c.write(vc);
    settle();
    EXPECT_EQ(inv44_y.read(), !va) << "row " << row;
    EXPECT_EQ(and40_y.read(), va && vb) << "row " << row;
    EXPECT_EQ(nand47_y.read(), !(va && vb)) << "row " << row;
    EXPECT_EQ(nand45_y.read(), !(va && vb && vc)) << "row " << row;
    EXPECT_EQ(nand46_y.read(), !(va && vb && vc)) << "row " << row;
  }
}

}  // namespace
}  // namespace specular
