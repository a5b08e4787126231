/// \file
/// Combinational adder 8 of Fig. 1.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Combinational adder 8: pin 20 (1.0) + inverter 7 + carry-in 34 = 1 − product;
/// saturates at 0 under Saturation::clamp (spec, Decision "negative results").
class Adder8 : public sc_core::sc_module {
 public:
  bus_in a20{"a20"};  ///< pin 20: the constant a (1.0 under the patent's constants), S14.22
  bus_in inverted{"inverted"};  ///< inverter 7's output, S14.22
  wire_in carry34{"carry34"};  ///< pin 34: carry-in, tied to 1
  bus_out sum{"sum"};  ///< a − product → register 9, S14.22

  /// Adder 8 on register 9's format (`formats` must outlive it), with `saturation`.
  Adder8(sc_core::sc_module_name name, const Formats& formats, Saturation saturation);

 private:
  void evaluate();
  const Formats& formats_;
  Saturation saturation_;
};

}  // namespace specular
