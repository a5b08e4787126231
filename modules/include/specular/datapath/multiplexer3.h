// Multiplexer 3 of Fig. 1: the ROM-5 address bus.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// in0 = register 1 (cos λ), in1 = register 9; select = control-unit output 36.
class Multiplexer3 : public sc_core::sc_module {
 public:
  bus_in reg1{"reg1"};
  bus_in reg9{"reg9"};
  wire_in select36{"select36"};
  bus_out address{"address"};

  Multiplexer3(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
