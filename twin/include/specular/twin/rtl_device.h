/// \file
/// The RTL twin behind the pin interface: rtl/device/specular_device.v, verilated into C++
/// and evaluated from this SystemC module, so that DeviceHarness, the protocol checker
/// and specular_tb drive it exactly as they drive the SystemC netlist.
#pragma once

#include "specular/device_harness.h"
#include "specular/protocol_checker.h"
#include "specular/twin/rtl_device_base.h"

namespace specular {

/// Pins 17–35 with the verilated drawn device behind them (RtlDeviceBase: one
/// SC_METHOD, the Config's policies tied off, Verilator's VCD), plus control unit 16's
/// flip-flops 41, 42 and NAND 45 for the protocol checker.
class RtlDevice : public RtlDeviceBase {
 public:
  /// `real_views` is accepted for DeviceHarness's sake and refused when true: the
  /// twin's waveform is Verilator's own (open_vcd), codes only.
  RtlDevice(sc_core::sc_module_name name, const Config& config = Config{},
            bool real_views = false);
  ~RtlDevice() override;

  // ---- what the protocol checker watches besides the pins (observation outputs) ----
  wire q41{"q41"};        ///< control unit 16: flip-flop 41's Q (start latched)
  wire q42{"q42"};        ///< control unit 16: flip-flop 42's Q (pass 1 pending)
  wire nand45{"nand45"};  ///< control unit 16: NAND 45's output

  /// Watches the pins and control unit 16, as in SpecularDevice (report_ids.h).
  ProtocolChecker protocol_checker{"protocol_checker"};

 private:
  static std::unique_ptr<Verilated> make_model(const Config& config);
};

/// The harness of the RTL twin: the `rtl` pin-level model of specular_tb.
using RtlHarness = DeviceHarness<RtlDevice>;
extern template class DeviceHarness<RtlDevice>;  // instantiated in rtl_device.cpp

}  // namespace specular
