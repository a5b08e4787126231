// The device of Fig. 1: datapath blocks and control unit 16 behind pins 17–35.
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

/// The pin-level device. Pins 19, 20 and 34 are wired constants in the patent (½, 1
/// and logic 1); they stay ports here (pin 19 carries h, pin 20 carries a: ½ and 1
/// only under the patent's constants), and `constant_h19()`, `constant_a20()` give
/// the codes a harness ties them to (pin19_code, pin20_code of the Config).
class SpecularDevice : public DevicePins {
 public:
  /// `real_views` adds real-valued mirrors of the main buses for VCD traces, for
  /// viewers that cannot show a code bus as fixed point (GTKWave can:
  /// waveforms/specular.gtkw); they cost about 1.3x the trace time.
  SpecularDevice(sc_core::sc_module_name name, const Config& config = Config{},
                 bool real_views = false);

  const Config& config() const { return config_; }
  const Formats& formats() const { return formats_; }
  code_t constant_h19() const { return pin19_code(formats_, config_.constants); }
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
  Register reg1{"reg1"};
  Register reg2{"reg2"};
  Multiplexer3 mux3;
  Multiplexer4 mux4;
  Rom5 rom5;
  Multiplier6 mul6;
  Inverter7 inv7;
  Adder8 adder8;
  Register reg9{"reg9"};
  Register reg10{"reg10"};
  Register reg11{"reg11"};
  Register reg12{"reg12"};
  MultiplierRgb mul13;
  MultiplierRgb mul14;
  MultiplierRgb mul15;
  Rom38 rom38;
  Multiplier39 mul39;
  ControlUnit16 cu16{"cu16"};
  /// Watches the pins and control unit 16; reports protocol misuse (report_ids.h).
  ProtocolChecker protocol_checker{"protocol_checker"};

  // ---- nets of Fig. 1, named after the block that drives them ----
  bus_signal reg1_q{"reg1_q"};
  bus_signal reg2_q{"reg2_q"};
  bus_signal mux3_address{"mux3_address"};
  bus_signal rom5_log2{"rom5_log2"};
  bus_signal mux4_operand{"mux4_operand"};
  bus_signal mul6_product{"mul6_product"};
  bus_signal inv7_inverted{"inv7_inverted"};
  bus_signal adder8_sum{"adder8_sum"};
  bus_signal reg9_q{"reg9_q"};
  bus_signal reg10_q{"reg10_q"};
  bus_signal reg11_q{"reg11_q"};
  bus_signal reg12_q{"reg12_q"};
  bus_signal rom38_k{"rom38_k"};
  bus_signal mul39_norm{"mul39_norm"};
  wire select36{"select36"};
  wire write37{"write37"};

 private:
  std::vector<std::unique_ptr<RealView>> real_views_;
};

}  // namespace specular
