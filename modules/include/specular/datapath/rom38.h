/// \file
/// ROM 38 of Fig. 1: the normalisation coefficient K(n).
#pragma once

#include "specular/arith.h"
#include "specular/systemc.h"

namespace specular {

/// ROM 38: K(n) addressed by register 2; contents set by the normalisation policy.
class Rom38 : public sc_core::sc_module {
 public:
  bus_in reg2{"reg2"};  ///< address: register 2 (n)
  bus_out k{"k"};  ///< the word s·K(n) (U9.16)

  /// ROM 38 reading `table` (which must outlive it).
  Rom38(sc_core::sc_module_name name, const arith::Rom38Table& table);

 private:
  void evaluate();
  const arith::Rom38Table& table_;
};

}  // namespace specular
