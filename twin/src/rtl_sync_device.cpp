#include "rtl_model.h"  // Verilator's headers first (see there)

#include "Vspecular_device_sync_cc.h"
#include "Vspecular_device_sync_cc___024root.h"
#include "Vspecular_device_sync_cc_fst.h"  // the same verilated with --trace-fst (issue 27)
#include "Vspecular_device_sync_cc_fst___024root.h"

#include "specular/twin/rtl_sync_device.h"

namespace specular {
namespace {

/// The sequencer's pass flag: the one net only the synchronous variant has.
struct SyncNets {
  using Device = RtlSyncDevice;
  std::uint64_t pass1;

  template <class Top, class Update>
  void update(Device& device, const Top& top, const Update& update) {
    update(pass1, top.obs_pass1, [&](std::uint64_t x) { device.pass1.write(x != 0); });
  }
};

}  // namespace

RtlSyncDevice::RtlSyncDevice(sc_core::sc_module_name name, const Config& config, bool real_views)
    : RtlDeviceBase(name, config, real_views,
                    {"RtlSyncDevice", "synchronous RTL twin", "waveforms/specular_rtl_sync.gtkw",
                     &RtlModel<Vspecular_device_sync_cc, SyncNets>::make,
                     &RtlModel<Vspecular_device_sync_cc_fst, SyncNets, VerilatedFstC>::make}) {}

RtlSyncDevice::~RtlSyncDevice() = default;

template class DeviceHarness<RtlSyncDevice>;

}  // namespace specular
