#include "specular/tlm/pin_target.h"

#include <stdexcept>

namespace specular {

const char* to_string(PinDelay delay) { return delay == PinDelay::keep ? "keep" : "consume"; }

PinDelay pin_delay_from_string(const std::string& text) {
  if (text == "keep") return PinDelay::keep;
  if (text == "consume") return PinDelay::consume;
  throw std::invalid_argument("pin delay policy '" + text + "' is not one of: keep, consume");
}

SpecularPinTarget::SpecularPinTarget(sc_core::sc_module_name name, const Config& config,
                                     const sc_core::sc_time& clock_period, bool real_views,
                                     PinDelay delay)
    : SpecularPinTarget(name, config, PinTargetSettings{clock_period, real_views, delay}) {}

SpecularPinTarget::SpecularPinTarget(sc_core::sc_module_name name, const Config& config,
                                     const PinTargetSettings& settings)
    : SpecularTarget(name, config, settings.clock_period),
      harness("harness", config, settings.clock_period, settings.real_views, ClockMode::on_demand),
      delay_policy_(settings.delay) {
  SPECULAR_HAS_PROCESS(SpecularPinTarget);
  set_energy_calibration(energy::Calibration::drawn_device);  // the netlist of Fig. 2
  SC_METHOD(on_reset);
  sensitive << harness.pin29_reset_n.negedge_event();
  dont_initialize();
  SC_THREAD(transact);
}

void SpecularPinTarget::on_reset() { reset_seen_ = true; }

void SpecularPinTarget::b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
  // Reads (and ignores) change nothing the pins use: served at once, they show the
  // registers as they are (STATUS.busy, the previous results) while an operation runs.
  if (tx.get_command() != tlm::TLM_WRITE_COMMAND) return SpecularTarget::b_transport(tx, delay);
  // A write waits for its turn: earlier writes (and the operations they run) first.
  const std::uint64_t ticket = next_ticket_++;
  while (ticket != serving_) sc_core::wait(turn_event_);
  SpecularTarget::b_transport(tx, delay);
  ++serving_;
  turn_event_.notify(sc_core::SC_ZERO_TIME);
}

void SpecularPinTarget::execute(const Operands& shared, const std::uint32_t* cos,
                                std::size_t count, std::uint32_t* out, Result& last,
                                sc_core::sc_time& delay) {
  if (delay_policy_ == PinDelay::consume) {
    // Synchronise: the pins live in simulated time, not in the initiator's local time.
    sc_core::wait(delay);
    delay = sc_core::SC_ZERO_TIME;
  }
  // PinDelay::keep: the pins run from now (the call's simulated time), and `delay` is
  // left as it came. This call then waits exactly the operation's latency (to pin 35),
  // and the initiator's time advances by that wait plus the unchanged delay: the
  // latency once, the delay once. (Running the pins at the local time now + delay
  // instead would need a wait of delay + latency somewhere, on top of a delay that may
  // not shrink: the delay twice.)
  operands_.assign(count, shared);
  for (std::size_t i = 0; i < count; ++i) operands_[i].cos = cos[i];
  // Hand the operands to the transactor and wait until pin 35 has risen on the last.
  job_done_ = false;
  job_posted_ = true;
  job_event_.notify(sc_core::SC_ZERO_TIME);
  while (!job_done_) sc_core::wait(done_event_);
  for (std::size_t i = 0; i < count; ++i)
    for (int ch = 0; ch < 3; ++ch) out[3 * i + ch] = static_cast<std::uint32_t>(results_[i].out[ch]);
  last = results_.back();
}

void SpecularPinTarget::transact() {
  for (;;) {
    while (!job_posted_) sc_core::wait(job_event_);
    job_posted_ = false;
    harness.clock_on();  // pin 28 runs only while there is work: an idle target costs nothing
    if (!reset_seen_) harness.reset();  // no start before a reset (spec §3)
    harness.run_batch(operands_, results_);
    harness.clock_off();
    job_done_ = true;
    done_event_.notify(sc_core::SC_ZERO_TIME);
  }
}

}  // namespace specular
