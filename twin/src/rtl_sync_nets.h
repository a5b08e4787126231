// The net only the synchronous variant observes, for RtlModel (rtl_model.h): shared by
// the general model (rtl_sync_device.cpp) and the specialised ones (the generated
// rtl_sync_fixed_table.cpp).
#pragma once

#include <cstdint>

#include "specular/twin/rtl_sync_device.h"

namespace specular {

/// The sequencer's pass flag.
struct SyncNets {
  using Device = RtlSyncDevice;
  std::uint64_t pass1;

  template <class Top, class Update>
  void update(Device& device, const Top& top, const Update& update) {
    update(pass1, top.obs_pass1, [&](std::uint64_t x) { device.pass1.write(x != 0); });
  }
};

}  // namespace specular
