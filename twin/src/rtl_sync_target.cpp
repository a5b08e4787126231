#include "specular/twin/rtl_sync_target.h"

#include "specular/twin/rtl_sync_cycle_model.h"

namespace specular {

SpecularRtlSyncTarget::SpecularRtlSyncTarget(sc_core::sc_module_name name, const Config& config,
                                             const sc_core::sc_time& clock_period)
    : SpecularTarget(name, config, clock_period),
      rtl_(std::make_unique<RtlSyncCycleModel>(config)) {
  rtl_->reset();
}

SpecularRtlSyncTarget::~SpecularRtlSyncTarget() = default;

void SpecularRtlSyncTarget::execute(const Operands& shared, const std::uint32_t* cos,
                                    std::size_t count, std::uint32_t* out, Result& last,
                                    sc_core::sc_time& delay) {
  batch_.assign(count, shared);
  for (std::size_t i = 0; i < count; ++i) batch_[i].cos = cos[i];
  results_.resize(count);
  const std::uint64_t before = rtl_->half_periods();
  rtl_->run_batch(batch_.data(), results_.data(), count);
  // The OUT format is at most 32 bits (checked at construction): two's complement.
  for (std::size_t i = 0; i < count; ++i)
    for (int ch = 0; ch < 3; ++ch) out[3 * i + ch] = static_cast<std::uint32_t>(results_[i].out[ch]);
  last = results_.back();
  // A batch starts with no operation in flight, on the first start's own rising edge,
  // and its last 35↑ is the rising edge before the final falling one: the clock edges
  // it took less those two, in half periods.
  delay += clock_period() * (static_cast<double>(rtl_->half_periods() - before - 2) / 2.0);
}

}  // namespace specular
