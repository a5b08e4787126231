// The specialised verilations of both twins built into this library
// (twin/fixed/rtl_sync_fixed.cmake writes the table, rtl_sync_fixed_table.cpp): for each
// configuration, how to make its cycle-model engines (RtlSyncCycleModel, RtlCycleModel)
// and its models behind RtlSyncDevice and RtlDevice.
#pragma once

#include <memory>

#include "specular/core.h"
#include "specular/twin/rtl_cycle_model.h"
#include "specular/twin/rtl_device_base.h"
#include "specular/twin/rtl_sync_cycle_model.h"

namespace specular {

struct RtlSyncFixedModel {
  Config config;
  std::unique_ptr<RtlSyncCycleModel::Engine> (*make_engine)(const Config&);
  std::unique_ptr<RtlDeviceBase::Verilated> (*make_device_model)(const Config&);
  std::unique_ptr<RtlCycleModel::Engine> (*make_drawn_engine)(const Config&);
  std::unique_ptr<RtlDeviceBase::Verilated> (*make_drawn_device_model)(const Config&);
};

/// The specialised model built for `config` (default widths, same policies), or null.
const RtlSyncFixedModel* rtl_sync_fixed_model(const Config& config);

}  // namespace specular
