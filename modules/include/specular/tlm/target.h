/// \file
/// The TLM-2.0 face of the device: a 32-bit target socket, the register file of
/// register_map.h, and the `done` interrupt. Two implementations sit behind it
/// (lt_target.h: the bit-accurate core with annotated latency; pin_target.h: a
/// transactor driving the pin-level netlist), so they cannot differ in how the
/// registers behave, only in how an operation is computed and timed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "specular/core.h"
#include "specular/energy/energy_meter.h"
#include "specular/systemc.h"
#include "specular/tlm/register_map.h"

namespace specular {

/// The register file and the bus checks, shared by every implementation.
///
/// Every access is checked as Accellera's LT examples do, in this order: address
/// (mapped; naturally aligned: 1 and 2 bytes inside a word, 4 on a word, 8 on a
/// doubleword, bursts on a word) → TLM_ADDRESS_ERROR_RESPONSE; length (1, 2, 4 or 8
/// on the registers, a multiple of 4 within a window) and streaming width (0 or at
/// least the length: no streaming) → TLM_BURST_ERROR_RESPONSE (a burst running past a
/// window's end is an address error); byte enables (only "all bytes" is accepted) →
/// TLM_BYTE_ENABLE_ERROR_RESPONSE; command (read, write, ignore; no writes to
/// read-only rows) → TLM_COMMAND_ERROR_RESPONSE. Out-of-range values get
/// TLM_GENERIC_ERROR_RESPONSE and are never clamped. Every refusal sets STATUS.error
/// with its cause and ERROR_ADDRESS; the refused access changes nothing else. The
/// first refusal of each cause is also reported (SC_REPORT_WARNING,
/// report::tlm_access_refused) naming the field, its value and the rule it breaks.
///
/// Access widths (docs/integration.md): a read of 1 or 2 bytes returns those bytes of
/// the word; a write of 1 or 2 bytes merges into STATUS (W1C), CONTROL and the operand
/// registers COS, N, R, G, B, the merged word checked as a whole; windows refuse
/// sub-word writes. An 8-byte access at a doubleword offset covers the two
/// consecutive registers there, all or nothing.
///
/// `done_irq` is a level: high while STATUS.done is set, i.e. from the end of an
/// operation until the next START (or BATCH_COS write) or a write of 1 to
/// STATUS.done. Its edges are scheduled at the initiator's annotated times; under
/// temporal decoupling a done/clear pair inside one quantum may not show as a pulse
/// (STATUS always shows it). It may be left unbound (the target then drives a signal
/// of its own), and on_done_irq() calls back at each of its edges.
class SpecularTarget : public sc_core::sc_module {
 public:
  /// The bus: bind an initiator socket or a router's; 32-bit data, the map of
  /// register_map.h at offsets 0 to map_size − 1.
  tlm_utils::simple_target_socket<SpecularTarget, 32> socket;
  /// The interrupt: a level, high while STATUS.DONE is set (see SpecularTarget); may
  /// stay unbound.
  sc_core::sc_out<bool> done_irq;

  /// Called at each edge of done_irq with its new level, from the process that drives
  /// it (an SC_METHOD: the callback must not wait). For interrupt controllers that
  /// take a call per interrupt rather than a signal; works bound or unbound.
  void on_done_irq(std::function<void(bool)> callback) {
    irq_callbacks_.push_back(std::move(callback));
  }
  /// The level done_irq drives (also when it is left unbound).
  bool done_irq_level() const { return irq_level_; }

  /// The configuration the target was built with (CONFIG reads it).
  const Config& config() const { return config_; }
  /// The bus formats derived from config().widths.
  const Formats& formats() const { return formats_; }
  /// The device's clock period T that the latencies are counted in.
  const sc_core::sc_time& clock_period() const { return period_; }

  /// The energy model (docs/energy.md): the energy spent so far, at the kernel's
  /// current time: the operations (charged with energy_calibration()'s gate-level fit),
  /// the register reads and writes, and every clock period since time 0 (the IP has no
  /// clock gating). All zero while the model is off (the default: set_energy_model).
  /// (Its types are named in full here: inside this class, `energy` is this function.)
  specular::energy::EnergyTally energy() const;
  /// The same at time `at` (e.g. an access's annotated time, sc_time_stamp() + delay):
  /// the clocks to `at`, the work charged so far.
  specular::energy::EnergyTally energy(const sc_core::sc_time& at) const;
  /// Whose gate-level figures the operations are charged: the drawn device for `pin`
  /// and `rtl`, the synchronous device (the IP's datapath) for the others.
  specular::energy::Calibration energy_calibration() const { return calibration_; }
  /// Switches the energy model on or off (off by default: it costs lt several times its
  /// own time per operation, docs/energy.md; off, an access costs one test more than
  /// without it). Switching off forgets what was counted; switch on before the first
  /// access whose energy should count.
  void set_energy_model(bool on);
  /// Whether the energy model is on.
  bool energy_model() const { return meter_ != nullptr; }
  /// Starts the power trace (and switches the energy model on): power_mw() becomes, at the end of each `window` (> 0), the
  /// mean power over it; an access's energy counts in the window of its annotated end
  /// (sc_time_stamp() + delay), so temporal decoupling shifts nothing. Call once, before
  /// or during the simulation (the windows start then); throws
  /// std::invalid_argument for a window ≤ 0 or a second call.
  void trace_power(const sc_core::sc_time& window);
  /// The power over the last window in mW (0 before the first window ends); trace it
  /// with sc_trace beside STATUS and done_irq (waveforms/specular_tlm_power.gtkw).
  const sc_core::sc_signal<double>& power_mw() const { return power_mw_; }
  /// Traces the target's view into `file` under this module's name: STATUS's busy,
  /// done and error, done_irq, power_mw and energy_pj (the sum of the windows' energy
  /// so far; both need trace_power()). waveforms/specular_tlm.gtkw shows them.
  void trace(sc_core::sc_trace_file* file) const;
  /// Called at the end of each power window with its end time and mean power in mW
  /// (for a CSV, a plot, a platform's own power bus); works without tracing.
  void on_power_window(std::function<void(const sc_core::sc_time&, double)> callback) {
    power_callbacks_.push_back(std::move(callback));
  }

  /// Start → results valid for `count` pipelined operations, in clock periods:
  /// 2.5 for one (spec §3, protocol Decision), 2 more per further operation while
  /// n and R, G, B stay unchanged (the pin model's streaming interval).
  static constexpr double latency_cycles(std::size_t count) { return 0.5 + 2.0 * static_cast<double>(count); }

 protected:
  /// Throws std::invalid_argument if a register-visible format does not fit 32 bits.
  SpecularTarget(sc_core::sc_module_name name, const Config& config,
                 const sc_core::sc_time& clock_period);

  /// The meter the operations are charged to, or nullptr when the model is off. An
  /// implementation whose execute() charges each operation itself (the results at
  /// hand: `lt`) says so with charges_operations_itself(); otherwise run() charges them,
  /// recomputed by the meter's own Core (pin, rtl, rtl_sync: bit-identical results).
  specular::energy::EnergyMeter* energy_meter() { return meter_.get(); }
  /// See energy_meter().
  void charges_operations_itself() { charges_itself_ = true; }
  /// The calibration charged (the constructor's default: the synchronous device).
  void set_energy_calibration(specular::energy::Calibration calibration);

  /// Runs `count` operations: cos λ from `cos[i]`, n and R, G, B from `shared`.
  /// Writes pins 24–26 of operation i to out[3i..3i+2] (32-bit two's complement) and
  /// everything of the last operation to `last`. Accounts for the time taken by
  /// adding to `delay` (annotation) or by waiting (`pin`: after consuming `delay`, or
  /// from now with `delay` kept, PinDelay).
  virtual void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
                       std::uint32_t* out, Result& last, sc_core::sc_time& delay) = 0;

  /// Every access from the socket (b_transport, and nb_transport_fw through the
  /// socket's nb-to-b conversion). An implementation whose `execute` waits serialises
  /// accesses around this (SpecularPinTarget: one at a time, in arrival order).
  virtual void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay);
  /// The debug transport (transport_dbg of the socket); `axi` reads over the RTL.
  virtual unsigned int transport_dbg(tlm::tlm_generic_payload& tx);
  /// For a target whose register file lives elsewhere (`axi`: in the RTL): done_irq
  /// takes `level` at `delay` after the current time (the base's own STATUS.done is
  /// then this level; the base's register file is otherwise unused).
  void rtl_done_irq(bool level, const sc_core::sc_time& delay);

  /// What an access tried, for the refusal's report.
  struct Attempt {
    tlm::tlm_command command;  ///< the payload's command
    std::uint64_t address;     ///< the payload's address
    unsigned length;           ///< the payload's data length
  };
  /// Why it is refused: the payload field or register, its value, the rule broken.
  struct Why {
    const char* field;    ///< the payload field or register name
    std::uint64_t value;  ///< its value
    const char* rule;     ///< the rule it broke
  };
  /// The checks of the class comment up to the byte enables (the payload's shape,
  /// before any register is touched); TLM_OK_RESPONSE if the access may go on to the
  /// command. `axi` runs them too: AXI4-Lite cannot carry a payload they refuse.
  tlm::tlm_response_status check_access(const tlm::tlm_generic_payload& tx,
                                        const Attempt& attempt, const RegisterInfo*& row);
  /// The value check of a write: the ranges of the operand rows, CONTROL's reserved
  /// bits; ErrorCause::none when `value` is acceptable.
  ErrorCause check_value(Reg reg, std::uint32_t value) const;
  /// The rule a refused address breaks: a hole, or beyond map_size.
  static const char* address_rule(std::uint64_t address);
  /// The rule a write to the read-only `row` breaks.
  static constexpr const char* read_only_rule = "a read-only register";
  /// Logs the first refusal of each cause (field, value, rule, STATUS's cause and
  /// `error_address`); later ones with that cause are only counted in STATUS.
  void report_refusal(tlm::tlm_response_status status, ErrorCause cause,
                      std::uint32_t error_address, const Attempt& attempt, const Why& why);

 private:
  /// A 1- or 2-byte access inside the word of `row` (byte lane address % 4).
  tlm::tlm_response_status sub_word(const RegisterInfo& row, const Attempt& attempt,
                                    unsigned char* data, sc_core::sc_time& delay);
  /// An 8-byte access on two single registers (`row` and the next word).
  tlm::tlm_response_status double_word(const RegisterInfo& row, const Attempt& attempt,
                                       unsigned char* data, sc_core::sc_time& delay);
  /// What a single-register write of `value` would be refused for, without doing it.
  tlm::tlm_response_status vet_write(const RegisterInfo& row, std::uint32_t value,
                                     const Attempt& attempt, std::uint64_t address);
  tlm::tlm_response_status write(const RegisterInfo& row, std::uint32_t first, std::uint32_t words,
                                 const unsigned char* data, std::uint64_t address,
                                 const Attempt& attempt, sc_core::sc_time& delay);
  void read(const RegisterInfo& row, std::uint32_t first, std::uint32_t words,
            unsigned char* data) const;
  /// One word as a read sees it (no side effects).
  std::uint32_t peek(const RegisterInfo& row, std::uint32_t word) const;
  /// A debug write: storage rows only, range-checked, no side effects.
  bool poke(const RegisterInfo& row, std::uint32_t word, std::uint32_t value);
  /// Sets STATUS.error, its cause and ERROR_ADDRESS (`address`, or 0xFFFFFFFF above
  /// 32 bits) and reports the first refusal of each cause; returns `status`.
  tlm::tlm_response_status refuse(tlm::tlm_response_status status, ErrorCause cause,
                                  std::uint64_t address, const Attempt& attempt, const Why& why);
  void run(const std::uint32_t* cos, std::size_t count, std::uint32_t* out,
           sc_core::sc_time& delay);
  std::uint32_t status_word() const;
  void drive_irq();

  std::uint32_t& word(Reg reg) { return words_[index_of(reg)]; }
  std::uint32_t word(Reg reg) const { return words_[index_of(reg)]; }

  Config config_;
  Formats formats_;
  sc_core::sc_time period_;
  std::array<std::uint32_t, register_count> words_{};  ///< single registers, by Reg
  std::vector<std::uint32_t> batch_cos_;
  std::vector<std::uint32_t> batch_out_;
  Result last_;
  bool busy_ = false;
  bool done_ = false;
  bool error_ = false;
  ErrorCause cause_ = ErrorCause::none;
  sc_core::sc_time done_at_;     ///< when done rises, in the initiator's (annotated) time
  sc_core::sc_event irq_event_;  ///< wakes drive_irq at the next edge of done_irq
  std::uint32_t reported_causes_ = 0;  ///< bit c: a refusal with cause c was reported
  bool irq_level_ = false;
  std::vector<std::function<void(bool)>> irq_callbacks_;

  /// The socket's b_transport: the implementation's, then the bus beats it cost.
  void transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay);
  /// Adds what was charged since the last call to the power window of `at`.
  void bin_energy(const sc_core::sc_time& at);
  void sample_power();  // the power trace's process
  double charged_pj() const;  // operations, reads and writes so far (no clocks)

  specular::energy::Calibration calibration_ = specular::energy::Calibration::synchronous_device;
  std::unique_ptr<specular::energy::EnergyMeter> meter_;
  bool charges_itself_ = false;
  sc_core::sc_time power_window_ = sc_core::SC_ZERO_TIME;  ///< zero: no power trace
  std::deque<double> power_bins_;  ///< pJ of windows from the current one on
  sc_core::sc_time window_start_;  ///< where power_bins_.front()'s window starts
  sc_core::sc_event power_on_;     ///< trace_power() was called
  double binned_pj_ = 0;           ///< charged_pj() when last binned
  sc_core::sc_signal<double> power_mw_{"power_mw", 0.0};
  double energy_pj_ = 0;           ///< the windows' energy so far (traced)
  std::vector<std::function<void(const sc_core::sc_time&, double)>> power_callbacks_;

  /// Binds done_irq to a signal of its own if nobody bound it by the end of
  /// elaboration (a child module, so that a derived target's own
  /// before_end_of_elaboration cannot skip it).
  struct DefaultIrqBinding : sc_core::sc_module {
    DefaultIrqBinding(sc_core::sc_module_name name, sc_core::sc_out<bool>& port);
    void before_end_of_elaboration() override;
    sc_core::sc_out<bool>& port;
    sc_core::sc_signal<bool> line;
  };
  DefaultIrqBinding irq_default_;
};

}  // namespace specular
