#include "specular/twin/rtl_target.h"

#include "specular/twin/rtl_cycle_model.h"

namespace specular {

SpecularRtlTarget::SpecularRtlTarget(sc_core::sc_module_name name, const Config& config,
                                     const sc_core::sc_time& clock_period)
    : SpecularTarget(name, config, clock_period), rtl_(std::make_unique<RtlCycleModel>(config)) {
  rtl_->reset();
  set_energy_calibration(energy::Calibration::drawn_device);  // Fig. 2 as drawn, as pin
}

SpecularRtlTarget::~SpecularRtlTarget() = default;

void SpecularRtlTarget::execute(const Operands& shared, const std::uint32_t* cos,
                                std::size_t count, std::uint32_t* out, Result& last,
                                sc_core::sc_time& delay) {
  batch_.assign(count, shared);
  for (std::size_t i = 0; i < count; ++i) batch_[i].cos = cos[i];
  const std::uint64_t before = rtl_->half_periods();
  rtl_->run_batch(batch_, results_);
  // The OUT format is at most 32 bits (checked at construction): two's complement.
  for (std::size_t i = 0; i < count; ++i)
    for (int ch = 0; ch < 3; ++ch) out[3 * i + ch] = static_cast<std::uint32_t>(results_[i].out[ch]);
  last = results_.back();
  // Every batch starts with no operation in flight, on the first start's own rising
  // edge, and ends at the last 35↑: the half periods after that first edge are the
  // batch's duration.
  delay += clock_period() * (static_cast<double>(rtl_->half_periods() - before - 1) / 2.0);
}

}  // namespace specular
