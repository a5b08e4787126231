#include "specular/tlm/lt_target.h"

namespace specular {

SpecularLtTarget::SpecularLtTarget(sc_core::sc_module_name name, const Config& config,
                                   const sc_core::sc_time& clock_period)
    : SpecularTarget(name, config, clock_period),
      core_(config),
      first_latency_(clock_period * latency_cycles(1)),
      stream_interval_(clock_period * (latency_cycles(2) - latency_cycles(1))) {
  charges_operations_itself();  // the results are at hand in execute()
}

void SpecularLtTarget::execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
                               std::uint32_t* out, Result& last, sc_core::sc_time& delay) {
  Operands op = shared;
  Result r;
  energy::EnergyMeter* const meter = energy_meter();
  for (std::size_t i = 0; i < count; ++i) {
    op.cos = cos[i];
    r = core_.run(op);
    if (meter != nullptr) meter->operation(op, r);
    // The OUT format is at most 32 bits (checked at construction): two's complement.
    for (int ch = 0; ch < 3; ++ch) out[3 * i + ch] = static_cast<std::uint32_t>(r.out[ch]);
  }
  last = r;
  delay += first_latency_;
  if (count > 1) delay += stream_interval_ * static_cast<double>(count - 1);
}

}  // namespace specular
