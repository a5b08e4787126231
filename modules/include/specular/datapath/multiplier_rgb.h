// Multipliers 13, 14, 15 of Fig. 1: one colour channel each.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Multiplier 39 × register 10, 11 or 12 → pin 24, 25 or 26.
class MultiplierRgb : public sc_core::sc_module {
 public:
  bus_in norm{"norm"};
  bus_in intensity{"intensity"};
  bus_out out{"out"};

  MultiplierRgb(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
