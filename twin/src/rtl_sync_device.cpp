#include "rtl_model.h"  // Verilator's headers first (see there)

#include "Vspecular_device_sync_cc.h"
#include "Vspecular_device_sync_cc___024root.h"
#include "Vspecular_device_sync_cc_fst.h"  // the same verilated with --trace-fst (issue 27)
#include "Vspecular_device_sync_cc_fst___024root.h"

#include "specular/twin/rtl_sync_device.h"
#include "rtl_sync_fixed.h"
#include "rtl_sync_nets.h"

namespace specular {

RtlSyncDevice::RtlSyncDevice(sc_core::sc_module_name name, const Config& config, bool real_views)
    : RtlDeviceBase(name, config, real_views,
                    {"RtlSyncDevice", "synchronous RTL twin", "waveforms/specular_rtl_sync.gtkw",
                     &make_model, &RtlModel<Vspecular_device_sync_cc, SyncNets>::make,
                     &RtlModel<Vspecular_device_sync_cc_fst, SyncNets, VerilatedFstC>::make, true}) {}

std::unique_ptr<RtlDeviceBase::Verilated> RtlSyncDevice::make_model(const Config& config) {
  // The specialised verilation when this configuration has one (untraced: open_vcd
  // replaces it by the general traced model), the general model otherwise.
  if (const RtlSyncFixedModel* fixed = rtl_sync_fixed_model(config))
    return fixed->make_device_model(config);
  return RtlModel<Vspecular_device_sync_cc, SyncNets>::make(config);
}

RtlSyncDevice::~RtlSyncDevice() = default;

template class DeviceHarness<RtlSyncDevice>;

}  // namespace specular
