#include "specular/control/d_flip_flop.h"

namespace specular {

DFlipFlop::DFlipFlop(sc_core::sc_module_name name) : sc_module(name) {
  SPECULAR_HAS_PROCESS(DFlipFlop);
  SC_METHOD(evaluate);
  sensitive << c.pos() << s_n << r_n;
  q.initialize(false);
  q_n.initialize(true);
}

void DFlipFlop::evaluate() {
  if (!r_n.read()) {
    state_ = false;
  } else if (!s_n.read()) {
    state_ = true;
  } else if (c.posedge()) {
    state_ = d.read();
  }
  q.write(state_);
  q_n.write(!state_);
}

}  // namespace specular
