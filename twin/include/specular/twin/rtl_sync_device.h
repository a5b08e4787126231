/// \file
/// The synchronous variant behind the pin interface: rtl/device/specular_device_sync.v,
/// verilated into C++ (traced) and evaluated from this SystemC module, so that
/// DeviceHarness (with the variant's protocol) and `specular_tb --model rtl-sync` drive it
/// as they drive the drawn device's twin (RtlDevice).
#pragma once

#include "specular/device_harness.h"
#include "specular/twin/rtl_device_base.h"

namespace specular {

/// Pins 17–35, as RtlDevice has them (RtlDeviceBase); inside, the verilated synchronous
/// device and one SC_METHOD that copies the pins into it, evaluates it and writes back
/// the outputs that changed. Start (27) and the loads (30–33) are levels sampled at
/// the rising edge of pin 28 (`synchronous`: DeviceHarness drives them so). Fig. 2's
/// nets (41, 42, NAND 45) do not exist here, so no ProtocolChecker watches it: the
/// sequencer ignores a start in pass 1 and has no other state to misuse (docs/rtl.md).
/// Default widths only; a Config with other widths, or one the core refuses, is
/// refused with std::invalid_argument.
class RtlSyncDevice : public RtlDeviceBase {
 public:
  /// Start and the loads are levels sampled at the rising clock edge (is_synchronous_device).
  static constexpr bool synchronous = true;

  /// `real_views` is refused when true, as in RtlDevice: the waveform is Verilator's.
  RtlSyncDevice(sc_core::sc_module_name name, const Config& config = Config{},
                bool real_views = false);
  ~RtlSyncDevice() override;

  // ---- what the harness watches besides RtlDeviceBase's (observation outputs) ----
  wire pass1{"pass1"};  ///< the sequencer's pass-1 state (obs_pass1 of rtl/device/control_unit_sync.v)

 private:
  static std::unique_ptr<Verilated> make_model(const Config& config);
};

/// The harness of the synchronous variant: `specular_tb --model rtl-sync`.
using RtlSyncHarness = DeviceHarness<RtlSyncDevice>;
extern template class DeviceHarness<RtlSyncDevice>;  // instantiated in rtl_sync_device.cpp

}  // namespace specular
