/// \file
/// Inverter block 7 of Fig. 1.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Inverter block 7: bitwise NOT of multiplier 6's product: with carry-in 34, adder 8 subtracts.
class Inverter7 : public sc_core::sc_module {
 public:
  bus_in product{"product"};  ///< multiplier 6's product, S14.22
  bus_out inverted{"inverted"};  ///< ~product, wrapped to S14.22 → adder 8

  /// Inverter 7 on register 9's format (`formats` must outlive it).
  Inverter7(sc_core::sc_module_name name, const Formats& formats);

 private:
  void evaluate();
  const Formats& formats_;
};

}  // namespace specular
