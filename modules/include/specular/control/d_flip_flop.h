/// \file
/// D flip-flops 41, 42, 43 of Fig. 2.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Rising-edge D flip-flop with asynchronous active-low reset R and set S
/// (R wins when both are low). Power-on state: Q = 0.
class DFlipFlop : public sc_core::sc_module {
 public:
  wire_in d{"d"};  ///< data input D
  wire_in c{"c"};        ///< clock input C
  wire_in s_n{"s_n"};    ///< asynchronous set, active low
  wire_in r_n{"r_n"};    ///< asynchronous reset, active low
  wire_out q{"q"};  ///< output Q
  wire_out q_n{"q_n"};  ///< output /Q

  /// A flip-flop at Q = 0.
  explicit DFlipFlop(sc_core::sc_module_name name);

 private:
  void evaluate();
  bool state_ = false;
};

}  // namespace specular
