/// \file
/// Control unit 16 (Fig. 2): three D flip-flops and five gates sequence two passes.
#pragma once

#include "specular/control/d_flip_flop.h"
#include "specular/control/gates.h"
#include "specular/systemc.h"

namespace specular {

/// Control unit 16: the gate-level netlist of Fig. 2, exactly the equations of spec §3:
/// \code{.unparsed}
///   inv44 = NOT clk;  and40 = rst_n AND nand45 → R of 41
///   dff41: C = start, D = 1;  dff42: C = inv44, D = Q41;  dff43: C = inv44, D = Q42
///   nand45 = NAND(/Q43, Q42, clk);  nand46 = NAND(clk, /Q42, Q43)
///   nand47 = NAND(nand45, nand46);  36 = Q43, 37 = nand47, 35 = nand46
/// \endcode
class ControlUnit16 : public sc_core::sc_module {
 public:
  wire_in start{"start"};      ///< input 1 ← pin 27
  wire_in clk{"clk"};          ///< input 2 ← pin 28
  wire_in reset_n{"reset_n"};  ///< input 3 ← pin 29
  wire_out select36{"select36"};  ///< output 1: multiplexers 3 and 4
  wire_out write37{"write37"};    ///< output 2: register 9 write strobe
  wire_out done35{"done35"};      ///< output 3 → pin 35

  /// Builds and wires the gates and flip-flops below.
  explicit ControlUnit16(sc_core::sc_module_name name);

  DFlipFlop dff41{"dff41"};     ///< flip-flop 41: start latched (C = start, D = 1)
  DFlipFlop dff42{"dff42"};     ///< flip-flop 42: pass 1 pending (C = inv44, D = Q41)
  DFlipFlop dff43{"dff43"};     ///< flip-flop 43: pass 2, select 36 (C = inv44, D = Q42)
  AndGate2 and40{"and40"};      ///< AND 40: reset of flip-flop 41
  NotGate inv44{"inv44"};       ///< inverter 44: clocks flip-flops 42 and 43
  NandGate3 nand45{"nand45"};   ///< NAND 45: pass-1 write window
  NandGate3 nand46{"nand46"};   ///< NAND 46: pass-2 write window, output 35
  NandGate2 nand47{"nand47"};   ///< NAND 47: register 9's write strobe, output 37

  // Nets of Fig. 2, public so that tests and traces can watch them.
  wire logic_one{"logic_one", true};  ///< the "logic 1" source of Fig. 2
  wire and40_y{"and40_y", true};  ///< idle value: reset_n AND nand45 = 1
  wire inv44_y{"inv44_y", true};  ///< inverter 44's output
  /// Flip-flop 41's output Q (start latched).
  wire q41{"q41"}, q41_n{"q41_n", true};
  /// \var q41_n
  /// Flip-flop 41's output /Q.

  /// Flip-flop 42's output Q (pass 1 pending).
  wire q42{"q42"}, q42_n{"q42_n", true};
  /// \var q42_n
  /// Flip-flop 42's output /Q.
  wire q43_n{"q43_n", true};      ///< flip-flop 43's /Q (its Q is output 36)
  wire nand45_y{"nand45_y", true};  ///< NAND 45's output

  /// Traces every net of Fig. 2 under this unit's name.
  void trace(sc_core::sc_trace_file* file) const;
};

}  // namespace specular
