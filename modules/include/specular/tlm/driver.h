/// \file
/// Software's view of the IP: what a CPU's driver does over the bus, for initiators
/// (the testbench, the example virtual platform, users' platforms).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <tlm>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "specular/core.h"
#include "specular/tlm/register_map.h"

namespace specular {

/// A refused transaction: names the access, the TLM response and STATUS's cause.
class TransportError : public std::runtime_error {
 public:
  /// `what`: the message (names the access); `status`: the TLM response; `cause`: STATUS.CAUSE.
  TransportError(const std::string& what, tlm::tlm_response_status status, ErrorCause cause)
      : std::runtime_error(what), status_(status), cause_(cause) {}
  /// The TLM response status the target returned.
  tlm::tlm_response_status status() const { return status_; }
  /// The cause STATUS[15:8] gave for the refusal.
  ErrorCause cause() const { return cause_; }

 private:
  tlm::tlm_response_status status_;
  ErrorCause cause_;
};

/// Software's view of a target from a SystemC initiator: registers, bursts and whole
/// operations, each access checked (TransportError on a refusal).
///
/// Register accesses through an initiator port (e.g. a tlm_utils::simple_initiator_socket)
/// with loosely-timed temporal decoupling: every transaction runs at the quantum
/// keeper's local time, and the keeper synchronises when its quantum is used up.
/// Call from an SC_THREAD. One generic payload is reused: no allocation per access.
class SpecularDriver {
 public:
  /// Any port or initiator socket with the TLM-2.0 forward interface.
  using port_type = sc_core::sc_port_b<tlm::tlm_fw_transport_if<>>;

  /// `base`: the IP's address on the bus behind `port`.
  SpecularDriver(port_type& port, std::uint64_t base, tlm_utils::tlm_quantumkeeper& keeper);

  /// Reads one register. Throws TransportError if the target refuses the access.
  std::uint32_t read(Reg reg);
  /// Writes one register. Throws TransportError if the target refuses the access
  /// (e.g. a value out of range: ErrorCause::n_out_of_range).
  void write(Reg reg, std::uint32_t value);
  /// Bursts of whole words at a byte offset from the base (e.g. the batch windows).
  /// Throws TransportError if the target refuses the access.
  void read_words(std::uint32_t offset, std::uint32_t* words, std::size_t count);
  /// A burst write of `count` words at `offset`; throws TransportError if refused.
  void write_words(std::uint32_t offset, const std::uint32_t* words, std::size_t count);

  /// One operation through the registers: N, R, G, B (those that changed since the
  /// driver last wrote them), COS, START, then OUT_R, OUT_G, OUT_B.
  std::array<std::int32_t, 3> compute(const Operands& in);
  /// The same operation in two bursts: one write of COS, N, R, G, B and START to the
  /// OPERANDS block, one read of OUT_R, OUT_G, OUT_B from RESULTS. The fast path for
  /// one operation whose n or R, G, B may change every time.
  std::array<std::int32_t, 3> compute_burst(const Operands& in);
  /// As compute(), and reads the inspection registers too: every field of Result.
  Result compute_inspected(const Operands& in);
  /// `count` operations sharing n and R, G, B, through BATCH_COS and BATCH_OUT
  /// (BATCH_CAPACITY per transaction pair). out[3i..3i+2] = pins 24–26 of op i.
  void compute_batch(code_t n, const std::array<code_t, 3>& rgb, const std::uint32_t* cos,
                     std::size_t count, std::int32_t* out);

  /// Start → results of the last compute*() call as the initiator saw it: the
  /// START (or BATCH_COS) writes' annotated delay plus any time the target waited.
  const sc_core::sc_time& operation_duration() const { return operation_duration_; }
  /// The quantum keeper whose local time the accesses use.
  tlm_utils::tlm_quantumkeeper& keeper() { return keeper_; }

 private:
  /// Sets up the one payload for a plain access (no byte enables, no streaming).
  void prepare(tlm::tlm_command command, std::uint32_t offset, unsigned char* data,
               unsigned length);
  /// `timed`: measure the transaction's duration into last_duration_ (operations only).
  void transport(tlm::tlm_command command, std::uint32_t offset, unsigned char* data,
                 unsigned length, bool timed = false);
  void load_shared(code_t n, const std::array<code_t, 3>& rgb);
  [[noreturn]] void fail(tlm::tlm_command command, std::uint32_t offset, unsigned length);

  port_type& port_;
  std::uint64_t base_;
  tlm_utils::tlm_quantumkeeper& keeper_;
  tlm::tlm_generic_payload tx_;
  sc_core::sc_time last_duration_;  ///< of the last transaction
  sc_core::sc_time operation_duration_;
  bool shared_loaded_ = false;
  code_t loaded_n_ = 0;
  std::array<code_t, 3> loaded_rgb_{};
};

}  // namespace specular
