/// \file
/// The gates of control unit 16 (Fig. 2): AND 40, inverter 44, NANDs 45, 46, 47.
/// Each is a plain combinational SC_METHOD; they differ only in their function.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Inverter 44: its output clocks flip-flops 42 and 43 on the clock's falling edge.
class NotGate : public sc_core::sc_module {
 public:
  wire_in a{"a"};  ///< input
  wire_out y{"y"};  ///< output: NOT a
  /// A gate named `name`; bind its ports.
  explicit NotGate(sc_core::sc_module_name name);

 private:
  void evaluate();
};

/// AND 40: reset of flip-flop 41 = reset pin 29 AND NAND 45.
class AndGate2 : public sc_core::sc_module {
 public:
  wire_in a{"a"};  ///< input
  wire_in b{"b"};  ///< input
  wire_out y{"y"};  ///< output: a AND b
  /// A gate named `name`; bind its ports.
  explicit AndGate2(sc_core::sc_module_name name);

 private:
  void evaluate();
};

/// NAND 47: register-9 write strobe 37 = NAND(NAND 45, NAND 46).
class NandGate2 : public sc_core::sc_module {
 public:
  wire_in a{"a"};  ///< input
  wire_in b{"b"};  ///< input
  wire_out y{"y"};  ///< output: NOT (a AND b)
  /// A gate named `name`; bind its ports.
  explicit NandGate2(sc_core::sc_module_name name);

 private:
  void evaluate();
};

/// NANDs 45 and 46: decode the pass-1 and pass-2 write windows from Q42, Q43, clock.
class NandGate3 : public sc_core::sc_module {
 public:
  wire_in a{"a"};  ///< input
  wire_in b{"b"};  ///< input
  wire_in c{"c"};  ///< input
  wire_out y{"y"};  ///< output: NOT (a AND b AND c)
  /// A gate named `name`; bind its ports.
  explicit NandGate3(sc_core::sc_module_name name);

 private:
  void evaluate();
};

}  // namespace specular
