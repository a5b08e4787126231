/// \file
/// Multiplier 39 of Fig. 1: register 9 × ROM 38.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Multiplier 39: K(n)·A, feeding multipliers 13–15. Saturates silently: between the
/// two passes register 9 holds the pass-1 value (up to ~16 000), which is not a result.
class Multiplier39 : public sc_core::sc_module {
 public:
  bus_in reg9{"reg9"};  ///< register 9 (A after pass 2)
  bus_in k{"k"};  ///< ROM 38: s·K(n) (U9.16)
  bus_out norm{"norm"};  ///< s·K·A (S10.20) → multipliers 13–15

  /// Multiplier 39 (`formats` must outlive it).
  Multiplier39(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
