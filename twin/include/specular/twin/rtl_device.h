// The RTL twin behind the pin interface: rtl/specular_device.v, verilated into C++
// and evaluated from this SystemC module, so that DeviceHarness, the protocol checker
// and specular_tb drive it exactly as they drive the SystemC netlist.
#pragma once

#include <memory>
#include <string>

#include "specular/core.h"
#include "specular/device_harness.h"
#include "specular/device_pins.h"
#include "specular/protocol_checker.h"
#include "specular/systemc.h"

namespace specular {

/// Pins 17–35 (DevicePins), as SpecularDevice has them. Inside, the
/// verilated model (Verilator's C++ output) and one SC_METHOD, sensitive to the
/// input pins, that copies the pins into the model, evaluates it and writes the
/// outputs that changed back, sign-extending the signed buses. One process activation per input
/// change: Verilator's own SystemC wrapper, with signals of its port types and
/// adapters in between, took about 4 process activations per clock edge and ran
/// slower than the netlist (docs/performance.md). Policies reach the model as its
/// configuration inputs, tied off here: cfg_literal = Saturation::literal,
/// cfg_rom38_bank = the ROM 38 image of the Config's constants and normalisation
/// (rom38_banks.h, docs/rtl.md); pins 19 and 20 carry the constants h and a.
///
/// The model is verilated at the default widths (docs/design.md); a Config with other
/// widths, or one the core refuses, is refused with std::invalid_argument.
class RtlDevice : public DevicePins {
 public:
  /// `real_views` is accepted for DeviceHarness's sake and refused when true: the
  /// twin's waveform is Verilator's own (open_vcd), codes only.
  RtlDevice(sc_core::sc_module_name name, const Config& config = Config{},
            bool real_views = false);
  ~RtlDevice() override;

  const Config& config() const { return config_; }
  const Formats& formats() const { return formats_; }
  code_t constant_h19() const { return pin19_code(config_); }
  code_t constant_a20() const { return pin20_code(config_); }

  /// The SystemC trace file gets nothing from the twin: its nets are traced by
  /// Verilator into the file open_vcd() names (GTKWave: waveforms/specular_rtl.gtkw).
  void trace(sc_core::sc_trace_file*) const override {}
  /// Trace every net of the RTL (pins, Fig. 1's buses, control unit 16) to `path`
  /// from the start of simulation on. Call before sc_start (std::logic_error after).
  void open_vcd(const std::string& path);

  // ---- what the harness and the protocol checker watch (observation outputs) ----
  wire select36{"select36"};
  wire q41{"q41"};
  wire q42{"q42"};
  wire nand45{"nand45"};
  bus_signal reg1_q{"reg1_q"};
  bus_signal reg9_q{"reg9_q"};
  bus_signal rom38_k{"rom38_k"};
  bus_signal mul39_norm{"mul39_norm"};

  /// Watches the pins and control unit 16, as in SpecularDevice (report_ids.h).
  ProtocolChecker protocol_checker{"protocol_checker"};

 private:
  struct Verilated;  // the verilated model, its VCD writer, the pins' channels (rtl_device.cpp)

  void before_end_of_elaboration() override;
  void end_of_elaboration() override;
  void start_of_simulation() override;
  void end_of_simulation() override;
  void evaluate();

  Config config_;
  Formats formats_;
  std::unique_ptr<Verilated> rtl_;
  std::string vcd_path_;
};

using RtlHarness = DeviceHarness<RtlDevice>;
extern template class DeviceHarness<RtlDevice>;  // instantiated in rtl_device.cpp

}  // namespace specular
