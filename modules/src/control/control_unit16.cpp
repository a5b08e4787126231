#include "specular/control/control_unit16.h"

namespace specular {

ControlUnit16::ControlUnit16(sc_core::sc_module_name name) : sc_module(name) {
  inv44.a(clk);
  inv44.y(inv44_y);

  and40.a(reset_n);
  and40.b(nand45_y);
  and40.y(and40_y);

  dff41.d(logic_one);
  dff41.c(start);
  dff41.s_n(logic_one);
  dff41.r_n(and40_y);
  dff41.q(q41);
  dff41.q_n(q41_n);

  dff42.d(q41);
  dff42.c(inv44_y);
  dff42.s_n(logic_one);
  dff42.r_n(reset_n);
  dff42.q(q42);
  dff42.q_n(q42_n);

  dff43.d(q42);
  dff43.c(inv44_y);
  dff43.s_n(logic_one);
  dff43.r_n(reset_n);
  dff43.q(select36);  // output 1 of the control unit is Q43
  dff43.q_n(q43_n);

  nand45.a(q43_n);
  nand45.b(q42);
  nand45.c(clk);
  nand45.y(nand45_y);

  nand46.a(clk);
  nand46.b(q42_n);
  nand46.c(select36);
  nand46.y(done35);

  nand47.a(nand45_y);
  nand47.b(done35);
  nand47.y(write37);
}

void ControlUnit16::trace(sc_core::sc_trace_file* file) const {
  const std::string scope = std::string(name()) + ".";
  for (const wire* net : {&and40_y, &inv44_y, &q41, &q42, &q43_n, &nand45_y})
    sc_core::sc_trace(file, *net, scope + net->basename());
}

}  // namespace specular
