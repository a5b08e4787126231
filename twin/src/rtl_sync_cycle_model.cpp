#include "specular/twin/rtl_sync_cycle_model.h"

#include <stdexcept>

#include <verilated.h>

#include "Vspecular_device_sync_fast.h"
#include "Vspecular_device_sync_fast___024root.h"
#include "rtl_sync_engine.h"
#include "rtl_sync_fixed.h"
#include "same_formats.h"

namespace specular {

RtlSyncCycleModel::RtlSyncCycleModel(const Config& config, bool allow_fixed) : config_(config) {
  const Formats formats(config.widths);
  arith::Rom38Table check(formats, config);  // a device the core refuses, the twin refuses too
  if (!same_formats(config.widths, Widths{}))
    throw std::invalid_argument(
        "the synchronous RTL twin is verilated at the default widths of docs/design.md only");
  const RtlSyncFixedModel* fixed = allow_fixed ? rtl_sync_fixed_model(config) : nullptr;
  if (fixed != nullptr)
    engine_ = fixed->make_engine(config);
  else
    engine_ = std::make_unique<SyncEngine<Vspecular_device_sync_fast, false>>(config);
}

RtlSyncCycleModel::~RtlSyncCycleModel() = default;

void RtlSyncCycleModel::reset() { engine_->reset(); }

Result RtlSyncCycleModel::run(const Operands& in) {
  std::vector<Result> out;
  run_batch({in}, out);
  return out.front();
}

void RtlSyncCycleModel::run_batch(const std::vector<Operands>& in, std::vector<Result>& out) {
  out.assign(in.size(), Result{});
  cycles_.assign(in.size(), 0.0);
  engine_->run_batch(in.data(), out.data(), cycles_.data(), in.size());
}

void RtlSyncCycleModel::run_batch(const Operands* in, Result* out, std::size_t count) {
  engine_->run_batch(in, out, nullptr, count);
}

std::uint64_t RtlSyncCycleModel::half_periods() const { return engine_->half_periods(); }

bool RtlSyncCycleModel::fixed() const { return engine_->fixed(); }

}  // namespace specular
