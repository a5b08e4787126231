#include "rtl_model.h"  // Verilator's headers first (see there)

#include "Vspecular_device_cc.h"
#include "Vspecular_device_cc___024root.h"
#include "Vspecular_device_cc_fst.h"  // the same verilated with --trace-fst (issue 27)
#include "Vspecular_device_cc_fst___024root.h"

#include "specular/twin/rtl_device.h"

namespace specular {
namespace {

/// Control unit 16's flip-flops 41, 42 and NAND 45 (Fig. 2): the nets only the drawn
/// device has, for the protocol checker.
struct Fig2Nets {
  using Device = RtlDevice;
  std::uint64_t q41, q42, nand45;

  template <class Top, class Update>
  void update(Device& device, const Top& top, const Update& update) {
    update(q41, top.obs_q41, [&](std::uint64_t x) { device.q41.write(x != 0); });
    update(q42, top.obs_q42, [&](std::uint64_t x) { device.q42.write(x != 0); });
    update(nand45, top.obs_nand45, [&](std::uint64_t x) { device.nand45.write(x != 0); });
  }
};

}  // namespace

RtlDevice::RtlDevice(sc_core::sc_module_name name, const Config& config, bool real_views)
    : RtlDeviceBase(name, config, real_views,
                    {"RtlDevice", "RTL twin", "waveforms/specular_rtl.gtkw",
                     &RtlModel<Vspecular_device_cc, Fig2Nets>::make,
                     &RtlModel<Vspecular_device_cc_fst, Fig2Nets, VerilatedFstC>::make}) {
  bind(protocol_checker, q41, q42, nand45);
  // NAND 45 starts high, as the netlist's does, until the first evaluation.
  nand45.write(true);
}

RtlDevice::~RtlDevice() = default;

template class DeviceHarness<RtlDevice>;

}  // namespace specular
