/// \file
/// Multiplexer 4 of Fig. 1: multiplier 6's second operand.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Multiplexer 4: in0 = register 2 (n), in1 = pin 19 (the constant ½); select =
/// control-unit output 36.
class Multiplexer4 : public sc_core::sc_module {
 public:
  bus_in reg2{"reg2"};  ///< in0: register 2 (n)
  bus_in h19{"h19"};  ///< in1: pin 19, the constant h (U10.8)
  wire_in select36{"select36"};  ///< control-unit output 36: 0 selects n, 1 selects h
  bus_out operand{"operand"};  ///< multiplier 6's second operand (U10.8)

  /// Multiplexer 4 (`formats` must outlive it).
  Multiplexer4(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
