/// \file
/// Multipliers 13, 14, 15 of Fig. 1: one colour channel each.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Multipliers 13–15: multiplier 39 × register 10, 11 or 12 → pin 24, 25 or 26.
class MultiplierRgb : public sc_core::sc_module {
 public:
  bus_in norm{"norm"};  ///< multiplier 39's output (S10.20)
  bus_in intensity{"intensity"};  ///< register 10, 11 or 12 (U8)
  bus_out out{"out"};  ///< pin 24, 25 or 26 (S18.13), saturated

  /// One of multipliers 13–15 (`formats` must outlive it).
  MultiplierRgb(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
