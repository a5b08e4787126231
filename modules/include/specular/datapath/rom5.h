/// \file
/// ROM 5 of Fig. 1: the log2 unit shared by both passes.
#pragma once

#include "specular/arith.h"
#include "specular/systemc.h"

namespace specular {

/// ROM 5: log2 of multiplexer 3's bus: leading-one detector + mantissa ROM (arith::Rom5Table).
class Rom5 : public sc_core::sc_module {
 public:
  bus_in address{"address"};  ///< multiplexer 3's bus (S14.22)
  bus_out log2{"log2"};  ///< log2 of the address (S5.22)

  /// ROM 5 reading `table` (which must outlive it).
  Rom5(sc_core::sc_module_name name, const arith::Rom5Table& table);

 private:
  void evaluate();
  const arith::Rom5Table& table_;
};

}  // namespace specular
