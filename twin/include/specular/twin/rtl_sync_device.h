// The synchronous variant behind the pin interface: rtl/specular_device_sync.v,
// verilated into C++ (traced) and evaluated from this SystemC module, so that
// DeviceHarness (with the variant's protocol) and specular_tb --model rtl-sync drive it
// as they drive the drawn device's twin (RtlDevice).
#pragma once

#include <memory>
#include <string>

#include "specular/core.h"
#include "specular/device_harness.h"
#include "specular/device_pins.h"
#include "specular/systemc.h"

namespace specular {

/// Pins 17–35 (DevicePins), as RtlDevice has them; inside, the verilated synchronous
/// device and one SC_METHOD that copies the pins into it, evaluates it and writes back
/// the outputs that changed. Start (27) and the loads (30–33) are levels sampled at
/// the rising edge of pin 28 (`synchronous`: DeviceHarness drives them so). Fig. 2's
/// nets (41, 42, NAND 45) do not exist here, so no ProtocolChecker watches it: the
/// sequencer ignores a start in pass 1 and has no other state to misuse (docs/rtl.md).
/// Default widths only; a Config with other widths, or one the core refuses, is
/// refused with std::invalid_argument.
class RtlSyncDevice : public DevicePins {
 public:
  static constexpr bool synchronous = true;

  /// `real_views` is refused when true, as in RtlDevice: the waveform is Verilator's.
  RtlSyncDevice(sc_core::sc_module_name name, const Config& config = Config{},
                bool real_views = false);
  ~RtlSyncDevice() override;

  const Config& config() const { return config_; }
  const Formats& formats() const { return formats_; }
  code_t constant_h19() const { return pin19_code(config_); }
  code_t constant_a20() const { return pin20_code(config_); }

  /// Nothing for SystemC's trace file: Verilator traces the RTL's nets to open_vcd()'s
  /// file (GTKWave: waveforms/specular_rtl_sync.gtkw).
  void trace(sc_core::sc_trace_file*) const override {}
  /// Trace every net of the RTL to `path` from the start of simulation on. Call before
  /// sc_start (std::logic_error after).
  void open_vcd(const std::string& path);

  // ---- what the harness watches (observation outputs) ----
  wire select36{"select36"};
  wire pass1{"pass1"};
  bus_signal reg1_q{"reg1_q"};
  bus_signal reg9_q{"reg9_q"};
  bus_signal rom38_k{"rom38_k"};
  bus_signal mul39_norm{"mul39_norm"};

 private:
  struct Verilated;  // the verilated model, its VCD writer, the pins' channels

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

using RtlSyncHarness = DeviceHarness<RtlSyncDevice>;
extern template class DeviceHarness<RtlSyncDevice>;  // instantiated in rtl_sync_device.cpp

}  // namespace specular
