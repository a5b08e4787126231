#include "specular/tlm/pin_target.h"

namespace specular {

SpecularPinTarget::SpecularPinTarget(sc_core::sc_module_name name, const Config& config,
                                     const sc_core::sc_time& clock_period, bool real_views)
    : SpecularTarget(name, config, clock_period),
      harness("harness", config, clock_period, real_views) {
  SPECULAR_HAS_PROCESS(SpecularPinTarget);
  SC_METHOD(on_reset);
  sensitive << harness.pin29_reset_n.negedge_event();
  dont_initialize();
}

void SpecularPinTarget::on_reset() { reset_seen_ = true; }

void SpecularPinTarget::execute(const Operands& shared, const std::uint32_t* cos,
                                std::size_t count, std::uint32_t* out, Result& last,
                                sc_core::sc_time& delay) {
  // Synchronise: the pins live in simulated time, not in the initiator's local time.
  sc_core::wait(delay);
  delay = sc_core::SC_ZERO_TIME;
  if (!reset_seen_) harness.reset();  // no start before a reset (spec §3)
  operands_.assign(count, shared);
  for (std::size_t i = 0; i < count; ++i) operands_[i].cos = cos[i];
  harness.run_batch(operands_, results_);
  for (std::size_t i = 0; i < count; ++i)
    for (int ch = 0; ch < 3; ++ch) out[3 * i + ch] = static_cast<std::uint32_t>(results_[i].out[ch]);
  last = results_.back();
}

}  // namespace specular
