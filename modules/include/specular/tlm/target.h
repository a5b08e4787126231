// The TLM-2.0 face of the device: a 32-bit target socket, the register file of
// register_map.h, and the `done` interrupt. Two implementations sit behind it
// (lt_target.h: the bit-accurate core with annotated latency; pin_target.h: a
// transactor driving the pin-level netlist), so they cannot differ in how the
// registers behave, only in how an operation is computed and timed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "specular/core.h"
#include "specular/systemc.h"
#include "specular/tlm/register_map.h"

namespace specular {

/// The register file and the bus checks, shared by both implementations.
///
/// Every access is checked as Accellera's LT examples do, in this order: address
/// (mapped, word-aligned) → TLM_ADDRESS_ERROR_RESPONSE; length (a multiple of 4; 4 on
/// a single register; within a window) and streaming width (no streaming) →
/// TLM_BURST_ERROR_RESPONSE (a burst running past a window's end is an address
/// error); byte enables (only "all bytes" is accepted) →
/// TLM_BYTE_ENABLE_ERROR_RESPONSE; command (read, write, ignore; no writes to
/// read-only rows) → TLM_COMMAND_ERROR_RESPONSE. Out-of-range values get
/// TLM_GENERIC_ERROR_RESPONSE and are never clamped. Every refusal sets STATUS.error
/// with its cause and ERROR_ADDRESS; the refused access changes nothing else.
///
/// `done_irq` is a level: high while STATUS.done is set, i.e. from the end of an
/// operation until the next START (or BATCH_COS write) or a write of 1 to
/// STATUS.done. Its edges are scheduled at the initiator's annotated times; under
/// temporal decoupling a done/clear pair inside one quantum may not show as a pulse
/// (STATUS always shows it).
class SpecularTarget : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<SpecularTarget, 32> socket;
  sc_core::sc_out<bool> done_irq;

  const Config& config() const { return config_; }
  const Formats& formats() const { return formats_; }
  const sc_core::sc_time& clock_period() const { return period_; }

  /// Start → results valid for `count` pipelined operations, in clock periods:
  /// 2.5 for one (spec §3, protocol Decision), 2 more per further operation while
  /// n and R, G, B stay unchanged (the pin model's streaming interval).
  static constexpr double latency_cycles(std::size_t count) { return 0.5 + 2.0 * static_cast<double>(count); }

 protected:
  /// Throws std::invalid_argument if a register-visible format does not fit 32 bits.
  SpecularTarget(sc_core::sc_module_name name, const Config& config,
                 const sc_core::sc_time& clock_period);

  /// Runs `count` operations: cos λ from `cos[i]`, n and R, G, B from `shared`.
  /// Writes pins 24–26 of operation i to out[3i..3i+2] (32-bit two's complement) and
  /// everything of the last operation to `last`. Accounts for the time taken by
  /// adding to `delay` (annotation) or by waiting (then `delay` is consumed first).
  virtual void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
                       std::uint32_t* out, Result& last, sc_core::sc_time& delay) = 0;

  /// Every access from the socket (b_transport, and nb_transport_fw through the
  /// socket's nb-to-b conversion). An implementation whose `execute` waits serialises
  /// accesses around this (SpecularPinTarget: one at a time, in arrival order).
  virtual void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay);

 private:
  unsigned int transport_dbg(tlm::tlm_generic_payload& tx);

  tlm::tlm_response_status write(const RegisterInfo& row, std::uint32_t first, std::uint32_t words,
                                 const unsigned char* data, std::uint64_t address,
                                 sc_core::sc_time& delay);
  void read(const RegisterInfo& row, std::uint32_t first, std::uint32_t words,
            unsigned char* data) const;
  /// One word as a read sees it (no side effects).
  std::uint32_t peek(const RegisterInfo& row, std::uint32_t word) const;
  /// A debug write: storage rows only, range-checked, no side effects.
  bool poke(const RegisterInfo& row, std::uint32_t word, std::uint32_t value);
  /// The value check of a write: the ranges of the operand rows, CONTROL's reserved
  /// bits; ErrorCause::none when `value` is acceptable.
  ErrorCause check_value(Reg reg, std::uint32_t value) const;
  tlm::tlm_response_status refuse(tlm::tlm_response_status status, ErrorCause cause,
                                  std::uint64_t address);
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
};

}  // namespace specular
