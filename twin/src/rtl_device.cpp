#include "rtl_model.h"  // Verilator's headers first (see there)

#include "Vspecular_device_cc.h"
#include "Vspecular_device_cc___024root.h"
#include "Vspecular_device_cc_fst.h"  // the same verilated with --trace-fst (issue 27)
#include "Vspecular_device_cc_fst___024root.h"

#include "specular/twin/rtl_device.h"
#include "rtl_drawn_nets.h"
#include "rtl_sync_fixed.h"

namespace specular {

RtlDevice::RtlDevice(sc_core::sc_module_name name, const Config& config, bool real_views)
    : RtlDeviceBase(name, config, real_views,
                    {"RtlDevice", "RTL twin", "waveforms/specular_rtl.gtkw",
                     &make_model, &RtlModel<Vspecular_device_cc, Fig2Nets>::make,
                     &RtlModel<Vspecular_device_cc_fst, Fig2Nets, VerilatedFstC>::make}) {
  bind(protocol_checker, q41, q42, nand45);
  // NAND 45 starts high, as the netlist's does, until the first evaluation.
  nand45.write(true);
}

std::unique_ptr<RtlDeviceBase::Verilated> RtlDevice::make_model(const Config& config) {
  // The specialised verilation when this configuration has one (untraced: open_vcd
  // replaces it by the general traced model), the general model otherwise.
  if (const RtlSyncFixedModel* fixed = rtl_sync_fixed_model(config))
    return fixed->make_drawn_device_model(config);
  return RtlModel<Vspecular_device_cc, Fig2Nets>::make(config);
}

RtlDevice::~RtlDevice() = default;

template class DeviceHarness<RtlDevice>;

}  // namespace specular
