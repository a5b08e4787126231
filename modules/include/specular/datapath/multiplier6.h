/// \file
/// Multiplier 6 of Fig. 1: ROM 5 × multiplexer 4.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Multiplier 6: log2 × (n in pass 1, ½ in pass 2), rounded to adder 8's format.
class Multiplier6 : public sc_core::sc_module {
 public:
  bus_in log2{"log2"};  ///< ROM 5's output (S5.22)
  bus_in operand{"operand"};  ///< multiplexer 4's output (U10.8)
  bus_out product{"product"};  ///< the product on register 9's format (S14.22), wrapped

  /// Multiplier 6 (`formats` must outlive it).
  Multiplier6(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
