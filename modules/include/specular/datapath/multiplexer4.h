// Multiplexer 4 of Fig. 1: multiplier 6's second operand.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// in0 = register 2 (n), in1 = pin 19 (the constant ½); select = control-unit output 36.
class Multiplexer4 : public sc_core::sc_module {
 public:
  bus_in reg2{"reg2"};
  bus_in h19{"h19"};
  wire_in select36{"select36"};
  bus_out operand{"operand"};

  Multiplexer4(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
