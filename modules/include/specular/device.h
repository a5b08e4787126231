/// \file
/// The device of Fig. 1: datapath blocks and control unit 16 behind pins 17–35.
#pragma once

#include <memory>
#include <vector>

#include "specular/arith.h"
#include "specular/control/control_unit16.h"
#include "specular/core.h"
#include "specular/datapath/adder8.h"
#include "specular/datapath/inverter7.h"
#include "specular/datapath/multiplexer3.h"
#include "specular/datapath/multiplexer4.h"
#include "specular/datapath/multiplier39.h"
#include "specular/datapath/multiplier6.h"
#include "specular/datapath/multiplier_rgb.h"
#include "specular/datapath/register.h"
#include "specular/datapath/rom38.h"
#include "specular/datapath/rom5.h"
#include "specular/device_pins.h"
#include "specular/protocol_checker.h"
#include "specular/real_view.h"
#include "specular/systemc.h"

namespace specular {

/// The pin-level SystemC device: the blocks of Fig. 1 and control unit 16 behind pins
/// 17–35, wired as the patent draws them.
///
/// Pins 19, 20 and 34 are wired constants in the patent (½, 1 and logic 1); they stay
/// ports here (pin 19 carries h, pin 20 carries a: ½ and 1
/// only under the patent's constants), and `constant_h19()`, `constant_a20()` give
/// the codes a harness ties them to (pin19_code, pin20_code of the Config).
class SpecularDevice : public DevicePins {
 public:
  /// `real_views` adds real-valued mirrors of the main buses for VCD traces, for
  /// viewers that cannot show a code bus as fixed point (GTKWave can:
  /// waveforms/specular.gtkw); they cost about 1.3x the trace time.
  SpecularDevice(sc_core::sc_module_name name, const Config& config = Config{},
                 bool real_views = false);

  /// The configuration the device was built with.
  const Config& config() const { return config_; }
  /// The bus formats derived from config().widths.
  const Formats& formats() const { return formats_; }
  /// The code to tie pin 19 to: h in multiplexer 4's format (pin19_code).
  code_t constant_h19() const { return pin19_code(formats_, config_.constants); }
  /// The code to tie pin 20 to: a in register 9's format (pin20_code).
  code_t constant_a20() const { return pin20_code(formats_, config_.constants); }

  /// Trace every net under this device's name, codes at their format's width, plus
  /// the real-valued views when the device was built with them.
  void trace(sc_core::sc_trace_file* file) const;

 private:
  Config config_;
  Formats formats_;
  arith::Rom5Table rom5_table_;
  arith::Rom38Table rom38_table_;

 public:
  // ---- blocks of Fig. 1 ----
  Register reg1{"reg1"};       ///< register 1: cos λ, written by pin 27
  Register reg2{"reg2"};       ///< register 2: n, written by pin 30
  Multiplexer3 mux3;           ///< multiplexer 3: ROM 5's address (register 1 or 9)
  Multiplexer4 mux4;           ///< multiplexer 4: multiplier 6's operand (n or h)
  Rom5 rom5;                   ///< ROM 5: log2
  Multiplier6 mul6;            ///< multiplier 6: ROM 5 × multiplexer 4
  Inverter7 inv7;              ///< inverter block 7: bitwise NOT of the product
  Adder8 adder8;               ///< combinational adder 8: a − product
  Register reg9{"reg9"};       ///< register 9: pass 1, then A; written by line 37
  Register reg10{"reg10"};     ///< register 10: R, written by pin 31
  Register reg11{"reg11"};     ///< register 11: G, written by pin 32
  Register reg12{"reg12"};     ///< register 12: B, written by pin 33
  MultiplierRgb mul13;         ///< multiplier 13: multiplier 39 × R → pin 24
  MultiplierRgb mul14;         ///< multiplier 14: multiplier 39 × G → pin 25
  MultiplierRgb mul15;         ///< multiplier 15: multiplier 39 × B → pin 26
  Rom38 rom38;                 ///< ROM 38: s·K(n), addressed by register 2
  Multiplier39 mul39;          ///< multiplier 39: register 9 × ROM 38
  ControlUnit16 cu16{"cu16"};  ///< control unit 16 (Fig. 2): sequences the two passes
  /// Watches the pins and control unit 16; reports protocol misuse (report_ids.h).
  ProtocolChecker protocol_checker{"protocol_checker"};

  // ---- nets of Fig. 1, named after the block that drives them ----
  bus_signal reg1_q{"reg1_q"};                ///< register 1's output (U1.16)
  bus_signal reg2_q{"reg2_q"};                ///< register 2's output (U10)
  bus_signal mux3_address{"mux3_address"};    ///< multiplexer 3 → ROM 5 (S14.22)
  bus_signal rom5_log2{"rom5_log2"};          ///< ROM 5 → multiplier 6 (S5.22)
  bus_signal mux4_operand{"mux4_operand"};    ///< multiplexer 4 → multiplier 6 (U10.8)
  bus_signal mul6_product{"mul6_product"};    ///< multiplier 6 → inverter 7 (S14.22)
  bus_signal inv7_inverted{"inv7_inverted"};  ///< inverter 7 → adder 8 (S14.22)
  bus_signal adder8_sum{"adder8_sum"};        ///< adder 8 → register 9 (S14.22)
  bus_signal reg9_q{"reg9_q"};                ///< register 9's output (S14.22)
  bus_signal reg10_q{"reg10_q"};              ///< register 10's output: R (U8)
  bus_signal reg11_q{"reg11_q"};              ///< register 11's output: G (U8)
  bus_signal reg12_q{"reg12_q"};              ///< register 12's output: B (U8)
  bus_signal rom38_k{"rom38_k"};              ///< ROM 38 → multiplier 39: s·K(n) (U9.16)
  bus_signal mul39_norm{"mul39_norm"};        ///< multiplier 39 → multipliers 13–15 (S10.20)
  wire select36{"select36"};                  ///< control output 36: multiplexer select
  wire write37{"write37"};                    ///< control output 37: register 9's write strobe

 private:
  std::vector<std::unique_ptr<RealView>> real_views_;
};

}  // namespace specular
