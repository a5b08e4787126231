// A recording pass-through for the IP's bus (issue 60): a module put between a test's CPU
// and its SpecularTarget (firmware_targets.h's Wiring) that passes every transaction
// through unchanged, its delay included, and logs it as the 32-bit AXI4-Lite beats it is
// on specular_ip_axi's bus, one line per beat, in the trace format the RTL SoC's replay
// bench reads (no header, no comments):
//     <op> <offset> <data> <strb> <resp>
// whitespace-separated hex: op 0 read, 1 write; offset the byte address minus the IP's
// base (the socket carries offsets: the CPUs' routers subtract the base); data the value
// written, or the value read; strb the beat's byte strobes (f for a read and a whole
// word); resp 0 OKAY, 2 SLVERR, 3 DECERR, mapped as twin/src/axi_target.cpp maps them
// (TLM_ADDRESS_ERROR_RESPONSE is DECERR, any other error SLVERR). A burst of k words is k
// beats; a 1- or 2-byte write is one beat at its byte address, its data on its lanes, the
// strobes of those lanes. A refused read records data 0, what specular_ip_axi drives with
// DECERR. An access with no beat form (a sub-word read: the other lanes are not in the
// payload; a refused burst: which beat the target refused is not either; byte enables,
// streaming, misalignment) is counted in unrecorded() and named, not guessed: a test
// expects none. Debug transport passes through unrecorded (it is not a bus access).
//
// Optionally a second target (the `check` target, e.g. lt) gets a copy of every access at
// the same annotated time and its answers are compared beat by beat with the recorded
// ones (response, and a read's data): a cross-check that the trace is the TLM model's
// answer, not only the RTL's. Beats on BATCH_CAPACITY and the batch windows are counted
// apart: there the RTL IP (capacity 0, windows DECERR) and lt (1024) differ by design.
// A test tool, not installed.
#ifndef SPECULAR_TESTS_SUPPORT_BUS_TRACE_RECORDER_H
#define SPECULAR_TESTS_SUPPORT_BUS_TRACE_RECORDER_H

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "specular/systemc.h"
#include "specular/tlm/register_map.h"
#include "specular/tlm/target.h"

namespace specular {
namespace testing_support {

class BusTraceRecorder : public sc_core::sc_module {
 public:
  /// One 32-bit AXI4-Lite beat: a line of the trace.
  struct Beat {
    std::uint32_t op;      ///< 0 read, 1 write
    std::uint32_t offset;  ///< byte address minus the IP's base
    std::uint32_t data;    ///< the value written, or read
    std::uint32_t strb;    ///< byte strobes (0xF: the whole word)
    std::uint32_t resp;    ///< 0 OKAY, 2 SLVERR, 3 DECERR
    bool operator==(const Beat& other) const {
      return op == other.op && offset == other.offset && data == other.data && strb == other.strb &&
             resp == other.resp;
    }
  };

  /// The cross-check's counts (all 0 without a check target).
  struct CheckTally {
    std::size_t beats = 0;        ///< beats compared
    std::size_t differences = 0;  ///< of those off BATCH_CAPACITY and the windows, how many differ
    std::size_t on_batch_rows = 0;             ///< beats on BATCH_CAPACITY or a window
    std::size_t on_batch_rows_different = 0;   ///< ... of which differ
    std::vector<std::string> first_differences;  ///< the first few, named (line, both beats)
  };

  tlm_utils::simple_target_socket<BusTraceRecorder, 32> target_socket;        ///< bind the CPU here
  tlm_utils::simple_initiator_socket<BusTraceRecorder, 32> initiator_socket;  ///< ... and this to the IP

  /// `check`: a target to cross-check every access against (owned and bound here), or
  /// none. `base`: subtracted from each address (0: the socket already carries offsets).
  BusTraceRecorder(sc_core::sc_module_name name, std::unique_ptr<SpecularTarget> check = nullptr,
                   std::uint64_t base = 0)
      : sc_module(name), target_socket("target_socket"), initiator_socket("initiator_socket"),
        check_(std::move(check)), base_(base) {
    target_socket.register_b_transport(this, &BusTraceRecorder::b_transport);
    target_socket.register_transport_dbg(this, &BusTraceRecorder::transport_dbg);
    if (check_) {
      check_socket_ = std::make_unique<tlm_utils::simple_initiator_socket<BusTraceRecorder, 32>>("check_socket");
      check_socket_->bind(check_->socket);
    }
  }

  const std::vector<Beat>& beats() const { return beats_; }
  /// Accesses with no beat form (see the file's comment); the first few named in notes().
  std::size_t unrecorded() const { return unrecorded_; }
  const std::vector<std::string>& notes() const { return notes_; }
  const CheckTally& check() const { return tally_; }

  /// A beat as its line of the trace (no newline).
  static std::string line(const Beat& beat) {
    char text[48];
    std::snprintf(text, sizeof text, "%x %04x %08x %x %x", beat.op, beat.offset, beat.data, beat.strb, beat.resp);
    return text;
  }

  /// Writes the trace to `path` (its folder made if missing); throws if it cannot.
  void write(const std::filesystem::path& path) const {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::trunc);
    for (const Beat& beat : beats_) out << line(beat) << '\n';
    out.close();
    if (!out) throw std::runtime_error("bus trace: cannot write " + path.string());
  }

  /// The AXI response for a TLM one, as the axi target maps them.
  static std::uint32_t axi_response(tlm::tlm_response_status status) {
    if (status == tlm::TLM_OK_RESPONSE) return 0u;
    return status == tlm::TLM_ADDRESS_ERROR_RESPONSE ? 3u : 2u;
  }

 private:
  static constexpr std::size_t notes_kept = 10;

  /// The beats of a completed access; false (and `why`) if it has none.
  bool beats_of(const tlm::tlm_generic_payload& tx, const unsigned char* written, std::vector<Beat>& out,
                std::string& why) const {
    out.clear();
    const auto none = [&why](const char* reason) {
      why = reason;
      return false;
    };
    const bool is_write = tx.get_command() == tlm::TLM_WRITE_COMMAND;
    const std::uint64_t address = tx.get_address();
    const unsigned length = tx.get_data_length();
    const tlm::tlm_response_status status = tx.get_response_status();
    if (status == tlm::TLM_INCOMPLETE_RESPONSE) return none("no response");
    if (address < base_ || address - base_ + length > 0x100000000ull) return none("outside the 32-bit map");
    if (tx.get_byte_enable_ptr() != nullptr) return none("byte enables");
    if (tx.get_streaming_width() != 0 && tx.get_streaming_width() < length) return none("streaming");
    const auto offset = static_cast<std::uint32_t>(address - base_);
    const std::uint32_t resp = axi_response(status);
    const unsigned char* data = is_write ? written : tx.get_data_ptr();
    if (length >= 4 && length % 4 == 0 && offset % 4 == 0) {
      if (resp != 0 && length > 4) return none("a refused burst");
      for (unsigned i = 0; i < length / 4; ++i) {
        std::uint32_t word = 0;
        if (is_write || resp == 0)
          for (unsigned b = 0; b < 4; ++b) word |= static_cast<std::uint32_t>(data[4 * i + b]) << (8 * b);
        out.push_back({is_write ? 1u : 0u, offset + 4 * i, word, 0xFu, resp});
      }
      return true;
    }
    if (is_write && (length == 1 || length == 2) && offset % 4 + length <= 4 && offset % length == 0) {
      const unsigned lane = offset % 4;
      std::uint32_t word = 0, strobes = 0;
      for (unsigned b = 0; b < length; ++b) {
        word |= static_cast<std::uint32_t>(data[b]) << (8 * (lane + b));
        strobes |= 1u << (lane + b);
      }
      out.push_back({1u, offset, word, strobes, resp});
      return true;
    }
    return none(is_write ? "a misaligned write" : length < 4 ? "a sub-word read" : "a misaligned read");
  }

  static bool on_batch_row(std::uint32_t offset) {
    const RegisterInfo* row = decode(offset & ~3u);
    return row != nullptr &&
           (row->reg == Reg::batch_capacity || row->reg == Reg::batch_cos || row->reg == Reg::batch_out);
  }

  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
    const tlm::tlm_command command = tx.get_command();
    const unsigned length = tx.get_data_length();
    const std::vector<unsigned char> written(tx.get_data_ptr(), tx.get_data_ptr() + length);  // as sent
    const sc_core::sc_time delay_in = delay;
    initiator_socket->b_transport(tx, delay);
    if (command == tlm::TLM_IGNORE_COMMAND) return;  // no bus access
    std::vector<Beat> recorded;
    std::string why;
    if (!beats_of(tx, written.data(), recorded, why)) {
      if (++unrecorded_ <= notes_kept)
        notes_.push_back("a " + std::to_string(length) + "-byte " +
                         (command == tlm::TLM_WRITE_COMMAND ? "write" : "read") + " at 0x" + hex(tx.get_address()) +
                         ": " + why);
      return;
    }
    const std::size_t first_line = beats_.size() + 1;
    beats_.insert(beats_.end(), recorded.begin(), recorded.end());
    if (check_socket_) cross_check(tx, written, delay_in, recorded, first_line);
  }

  /// The same access on the check target, at the same time; its beats against `recorded`.
  void cross_check(const tlm::tlm_generic_payload& tx, const std::vector<unsigned char>& written,
                   const sc_core::sc_time& delay_in, const std::vector<Beat>& recorded, std::size_t first_line) {
    std::vector<unsigned char> data = tx.get_command() == tlm::TLM_WRITE_COMMAND
                                          ? written
                                          : std::vector<unsigned char>(written.size(), 0);
    tlm::tlm_generic_payload copy;
    copy.set_command(tx.get_command());
    copy.set_address(tx.get_address());
    copy.set_data_ptr(data.data());
    copy.set_data_length(tx.get_data_length());
    copy.set_streaming_width(tx.get_streaming_width());
    copy.set_byte_enable_ptr(nullptr);
    copy.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_core::sc_time delay = delay_in;  // its own timing is not the recording's
    (*check_socket_)->b_transport(copy, delay);
    std::vector<Beat> answered;
    std::string why;
    const bool shaped = beats_of(copy, written.data(), answered, why);
    for (std::size_t i = 0; i < recorded.size(); ++i) {
      const bool same = shaped && i < answered.size() && answered[i] == recorded[i];
      ++tally_.beats;
      if (on_batch_row(recorded[i].offset)) {
        ++tally_.on_batch_rows;
        tally_.on_batch_rows_different += !same;
        continue;
      }
      if (same) continue;
      if (++tally_.differences <= notes_kept)
        tally_.first_differences.push_back("line " + std::to_string(first_line + i) + ": recorded '" +
                                           line(recorded[i]) + "', check target '" +
                                           (shaped && i < answered.size() ? line(answered[i]) : why) + "'");
    }
  }

  unsigned int transport_dbg(tlm::tlm_generic_payload& tx) { return initiator_socket->transport_dbg(tx); }

  static std::string hex(std::uint64_t value) {
    char text[24];
    std::snprintf(text, sizeof text, "%llx", static_cast<unsigned long long>(value));
    return text;
  }

  std::unique_ptr<SpecularTarget> check_;
  std::unique_ptr<tlm_utils::simple_initiator_socket<BusTraceRecorder, 32>> check_socket_;
  std::uint64_t base_;
  std::vector<Beat> beats_;
  std::size_t unrecorded_ = 0;
  std::vector<std::string> notes_;
  CheckTally tally_;
};

}  // namespace testing_support
}  // namespace specular

#endif  // SPECULAR_TESTS_SUPPORT_BUS_TRACE_RECORDER_H
