/// \file
/// Registers 1, 2, 9, 10, 11, 12 of Fig. 1: an edge-triggered register of one bus.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Registers 1, 2, 9 and 10–12: captures `d` on the rising edge of its write strobe
/// (spec: "written by the leading edge"); holds its power-on value until the first write.
class Register : public sc_core::sc_module {
 public:
  bus_in d{"d"};  ///< data in
  wire_in load{"load"};  ///< write strobe: pin 27, 30–33, or control-unit output 37
  bus_out q{"q"};  ///< data out: the last value captured

  /// A register that outputs `power_on_value` until its first write.
  Register(sc_core::sc_module_name name, code_t power_on_value = 0);

 private:
  void capture();
  code_t power_on_value_;
};

}  // namespace specular
