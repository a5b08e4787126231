/// \file
/// `pin`: the TLM target as a transactor in front of the pin-level netlist.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "specular/pin_harness.h"
#include "specular/tlm/target.h"

namespace specular {

/// What SpecularPinTarget's b_transport does with the initiator's annotated delay
/// (docs/integration.md §6). Both give the same bits and the same pins relative to
/// the call; they differ in where the pins sit in simulated time and in the delay
/// returned.
enum class PinDelay : std::uint8_t {
  /// Wait the delay out, then run the pins; return 0. The pins sit at the initiator's
  /// local time; the delay shrinks (legal, but refused by initiators that assert it).
  consume,
  /// Run the pins from the call's simulated time and return the delay unchanged: the
  /// call waits exactly the operation's latency (start edge, then pin 35), which is the
  /// time the initiator gains, so nothing is counted twice and the delay never
  /// shrinks. For initiators that assert it does not (riscv-vp's memory interface).
  /// The default (PinTargetSettings).
  keep,
};

/// "keep" or "consume".
const char* to_string(PinDelay delay);
/// PinDelay from "keep" or "consume"; throws std::invalid_argument naming the value and
/// the allowed ones (for options such as specular_tb's and soc_platform's `--pin-delay`).
PinDelay pin_delay_from_string(const std::string& text);

/// SpecularPinTarget's configuration beyond the device's Config (issue 35): set its
/// fields by name, e.g. `PinTargetSettings settings; settings.delay = PinDelay::consume;`.
struct PinTargetSettings {
  sc_core::sc_time clock_period = sc_core::sc_time(10, sc_core::SC_NS);  ///< pin 28's period
  bool real_views = false;  ///< PinHarness's real-valued views (traces)
  /// What b_transport does with the annotated delay. Default keep: the delay never
  /// shrinks, which every initiator accepts and riscv-vp's memory interface asserts
  /// (docs/integration.md §6).
  PinDelay delay = PinDelay::keep;
};

/// The `pin` target: SpecularTarget's register file computed by the pin-level device,
/// cycle-accurate. See SpecularTarget for the registers, the bus checks and done_irq.
///
/// Drives the device of Fig. 1 through PinHarness, as a TLM-to-pin bridge does
/// (compare Xilinx libsystemctlm-soc's tlm2apb-bridge). Cycle-accurate: an operation
/// first waits out the initiator's annotated delay (PinDelay::consume; with
/// PinDelay::keep it starts from the call's time and leaves the delay as it came), then
/// the transactor drives pins
/// 17–33 and waits on the clock (pin 28) until pin 35 rises. START begins at the next
/// rising clock edge at least a quarter period away (the harness's protocol); a batch
/// streams one operation every 2 periods. If pin 29 was never pulsed since power-on,
/// the first operation first resets the control unit (one clock period), as spec §3
/// wants before any start. Pin 28 runs on demand (ClockMode::on_demand): from the
/// operation's first edge to a few periods after pin 35 rises, on the grid of a clock
/// that had run from time 0, so an idle target schedules nothing and sc_start()
/// without a time end returns once the initiators are done.
///
/// The transactor owns the pins: one SC_THREAD of its own (`transact`) writes them,
/// whoever calls (SystemC's one-writer rule). Writes are served one at a time in the
/// order they arrive, as a bus bridge serialises them: while an operation runs, a
/// write from any other thread (b_transport, or nb_transport_fw through the socket's
/// nb-to-b threads) waits until pin 35 has risen and the operation's b_transport has
/// returned, then runs — a START or an operand write waits its turn instead of being
/// refused as busy. Reads never wait: they see STATUS.busy and the previous results
/// while an operation runs. Debug transport never waits. Call b_transport from a
/// thread (SC_THREAD or spawned). PinTargetSettings::delay picks what b_transport does
/// with the annotated delay (PinDelay: keep, the default, or consume).
class SpecularPinTarget : public SpecularTarget {
 public:
  /// A transactor over a SpecularDevice built from `config`, with `settings` (clock
  /// period, real views, delay policy). Throws std::invalid_argument as
  /// SpecularTarget's constructor does.
  SpecularPinTarget(sc_core::sc_module_name name, const Config& config,
                    const PinTargetSettings& settings);
  /// The positional form, as before; `delay` now defaults to keep, as the settings do.
  SpecularPinTarget(sc_core::sc_module_name name, const Config& config = Config{},
                             const sc_core::sc_time& clock_period = sc_core::sc_time(10, sc_core::SC_NS),
                             bool real_views = false, PinDelay delay = PinDelay::keep);

  PinHarness harness;  ///< the pin-level device and its driver (on-demand clock)
  /// What b_transport does with the annotated delay (PinTargetSettings::delay).
  PinDelay delay_policy() const { return delay_policy_; }

 protected:
  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) override;

 private:
  void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
               std::uint32_t* out, Result& last, sc_core::sc_time& delay) override;

  void transact();  // the one process that drives the pins
  void on_reset();  // pin 29 fell: the control unit has seen a reset

  PinDelay delay_policy_;
  bool reset_seen_ = false;
  std::vector<Operands> operands_;
  std::vector<Result> results_;

  // Turns: a ticket per write, served in ticket order (FIFO), as a bus bridge serialises.
  std::uint64_t next_ticket_ = 0;
  std::uint64_t serving_ = 0;
  sc_core::sc_event turn_event_;

  // The hand-over between the access in turn and the transactor.
  bool job_posted_ = false;
  bool job_done_ = false;
  sc_core::sc_event job_event_;
  sc_core::sc_event done_event_;
};

}  // namespace specular
