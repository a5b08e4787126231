/// \file
/// `lt`: the TLM target computed by the bit-accurate core, loosely timed.
#pragma once

#include "specular/core.h"
#include "specular/tlm/target.h"

namespace specular {

/// The `lt` target: SpecularTarget's register file computed by the bit-accurate Core,
/// loosely timed. See SpecularTarget for the registers, the bus checks and done_irq.
///
/// Calls Core::run (the same per-block functions as the netlist, hence the same
/// bits) and annotates the pin model's latency on b_transport's `delay`: 2.5 clock
/// periods for START, 2.5 + 2·(k − 1) for a batch of k (SpecularTarget::latency_cycles).
/// It has no clock and never waits, so initiators may run ahead under a
/// tlm_utils::tlm_quantumkeeper. No allocation, no formatting per transaction.
class SpecularLtTarget : public SpecularTarget {
 public:
  /// A target computing with a Core built from `config`. `clock_period` is the device's
  /// clock T that the annotated latency counts in (10 ns by default;
  /// osu018_clock_period() for the silicon's).
  /// Throws std::invalid_argument as SpecularTarget's constructor and Core's do.
  explicit SpecularLtTarget(sc_core::sc_module_name name, const Config& config = Config{},
                            const sc_core::sc_time& clock_period = sc_core::sc_time(10, sc_core::SC_NS));

  /// The core that computes every operation.
  const Core& core() const { return core_; }

 private:
  void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
               std::uint32_t* out, Result& last, sc_core::sc_time& delay) override;

  Core core_;
  sc_core::sc_time first_latency_;    ///< start → 35↑ of one operation
  sc_core::sc_time stream_interval_;  ///< start-to-start while only cos λ changes
};

}  // namespace specular
