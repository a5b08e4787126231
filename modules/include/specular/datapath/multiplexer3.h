/// \file
/// Multiplexer 3 of Fig. 1: the ROM-5 address bus.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Multiplexer 3: in0 = register 1 (cos λ), in1 = register 9; select = control-unit output 36.
class Multiplexer3 : public sc_core::sc_module {
 public:
  bus_in reg1{"reg1"};  ///< in0: register 1 (cos λ, U1.16)
  bus_in reg9{"reg9"};  ///< in1: register 9 (S14.22)
  wire_in select36{"select36"};  ///< control-unit output 36: 0 selects register 1, 1 register 9
  bus_out address{"address"};  ///< ROM 5's address on register 9's format

  /// Multiplexer 3 (`formats` must outlive it).
  Multiplexer3(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
