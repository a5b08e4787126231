// The nets only the drawn twin observes, for RtlModel (rtl_model.h): shared by the
// general model (rtl_device.cpp) and the specialised ones (rtl_sync_fixed_table.cpp).
#pragma once

#include <cstdint>

#include "specular/twin/rtl_device.h"

namespace specular {

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


}  // namespace specular
