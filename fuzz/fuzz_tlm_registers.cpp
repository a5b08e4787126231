// libFuzzer target: the TLM-2.0 register interface. Each input is a sequence of
// bus transactions (any command, address, length, byte enables, streaming width and
// data) sent to BOTH implementations — `lt` (the bit-accurate core) and `pin` (the
// transactor in front of the pin-level netlist). Findings:
//   - a crash, an exception out of the kernel, undefined behaviour (ASan/UBSan);
//   - the two targets answering differently (response, read data, debug bytes);
//   - a refusal whose STATUS cause does not match its TLM response;
//   - a protocol report from the pin device (the transactor must never misuse pins).
//
// The design is elaborated once in LLVMFuzzerInitialize; each input wakes the
// initiator thread, which resets both targets, replays the transactions and pauses
// the simulation (sc_pause), so sc_start() returns to libFuzzer.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "specular/report_ids.h"
#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "fuzz_bytes.h"

// libsystemc refers to sc_main; libFuzzer's main() runs instead, so it is never called.
extern "C" int sc_main(int, char**) { return 0; }

namespace {

using namespace specular;
using sc_core::sc_time;
using sc_core::SC_NS;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_tlm_registers: %s\n", what.c_str());
  std::abort();
}

using specular_fuzz::Bytes;

/// Which STATUS cause each refusal must leave (target.h's order of checks).
bool cause_matches(tlm::tlm_response_status response, ErrorCause cause) {
  switch (response) {
    case tlm::TLM_ADDRESS_ERROR_RESPONSE: return cause == ErrorCause::address;
    case tlm::TLM_BURST_ERROR_RESPONSE: return cause == ErrorCause::burst;
    case tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE: return cause == ErrorCause::byte_enable;
    case tlm::TLM_COMMAND_ERROR_RESPONSE:
      return cause == ErrorCause::read_only || cause == ErrorCause::command;
    case tlm::TLM_GENERIC_ERROR_RESPONSE:
      return cause == ErrorCause::cos_out_of_range || cause == ErrorCause::n_out_of_range ||
             cause == ErrorCause::rgb_out_of_range || cause == ErrorCause::reserved_bits ||
             cause == ErrorCause::busy;
    default: return false;
  }
}

constexpr std::size_t max_transactions = 48;
constexpr unsigned max_length = 256;  // bytes; larger bursts only cost time on `pin`

class Bench : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<Bench, 32> to_lt{"to_lt"};
  tlm_utils::simple_initiator_socket<Bench, 32> to_pin{"to_pin"};
  SpecularLtTarget lt{"lt"};
  SpecularPinTarget pin{"pin"};
  sc_core::sc_signal<bool> lt_irq{"lt_irq"};
  sc_core::sc_signal<bool> pin_irq{"pin_irq"};

  explicit Bench(sc_core::sc_module_name name) : sc_module(name) {
    SPECULAR_HAS_PROCESS(Bench);
    to_lt.bind(lt.socket);
    to_pin.bind(pin.socket);
    lt.done_irq(lt_irq);
    pin.done_irq(pin_irq);
    SC_THREAD(run);
  }

  void start(const std::uint8_t* data, std::size_t size) {
    data_ = data;
    size_ = size;
    go_.notify(sc_core::SC_ZERO_TIME);
  }

 private:
  void run() {
    while (true) {
      wait(go_);
      reset();
      replay(Bytes(data_, size_));
      sc_core::sc_pause();
    }
  }

  /// Both targets back to their reset state, as far as the bus can put them.
  void reset() {
    pin.harness.reset();  // pin 29: the control unit to idle
    std::vector<std::uint32_t> zeros(batch_capacity, 0);
    for (SpecularTarget* target : {static_cast<SpecularTarget*>(&lt), static_cast<SpecularTarget*>(&pin)}) {
      auto& socket = target == &lt ? to_lt : to_pin;
      const std::uint32_t status_clear = status_bits::done | status_bits::error;
      write(socket, offset_of(Reg::status), &status_clear, 1);
      for (const Reg reg : {Reg::cos, Reg::n, Reg::r, Reg::g, Reg::b}) {
        const std::uint32_t value = info(reg).reset;
        write(socket, offset_of(reg), &value, 1);
      }
      tlm::tlm_generic_payload tx;  // BATCH_COS through the debug port: no operation runs
      tx.set_command(tlm::TLM_WRITE_COMMAND);
      tx.set_address(offset_of(Reg::batch_cos));
      tx.set_data_ptr(reinterpret_cast<unsigned char*>(zeros.data()));
      tx.set_data_length(4 * batch_capacity);
      if (socket->transport_dbg(tx) != 4 * batch_capacity) finding("reset of BATCH_COS failed");
    }
  }

  void write(tlm_utils::simple_initiator_socket<Bench, 32>& socket, std::uint32_t offset,
             const std::uint32_t* words, unsigned count) {
    tlm::tlm_generic_payload tx;
    tx.set_command(tlm::TLM_WRITE_COMMAND);
    tx.set_address(offset);
    tx.set_data_ptr(reinterpret_cast<unsigned char*>(const_cast<std::uint32_t*>(words)));
    tx.set_data_length(4 * count);
    tx.set_streaming_width(4 * count);
    sc_time delay = sc_core::SC_ZERO_TIME;
    socket->b_transport(tx, delay);
    if (tx.get_response_status() != tlm::TLM_OK_RESPONSE) finding("reset write refused");
  }

  /// One generic payload built from the input, sent to `socket`.
  struct Request {
    tlm::tlm_command command = tlm::TLM_READ_COMMAND;
    std::uint64_t address = 0;
    unsigned length = 4;
    unsigned streaming_width = 4;
    std::vector<unsigned char> enables;
    bool with_enables = false;
    bool debug = false;
    std::vector<unsigned char> data;
  };

  Request decode(Bytes& in) {
    Request r;
    const std::uint8_t kind = in.u8();
    r.command = static_cast<tlm::tlm_command>(kind & 3);  // read, write, ignore, or 3 (none)
    r.debug = (kind & 0x80) != 0;
    // Address: mostly a mapped row (and a word in it), sometimes any offset.
    const std::uint8_t where = in.u8();
    if (where & 0x80) {
      r.address = in.u16() & 0x7FFF;
      if (where & 0x40) r.address |= std::uint64_t{in.u32()} << 15;  // far beyond the map
    } else {
      const RegisterInfo& row = register_map[where % register_count];
      r.address = row.offset + 4 * (in.u16() % row.words);
      if (where & 0x40) r.address += in.u8() % 4;  // misaligned
    }
    // Length: one word mostly; a few words, odd sizes or a long burst otherwise.
    const std::uint8_t size = in.u8();
    switch (size >> 6) {
      case 0: r.length = 4; break;
      case 1: r.length = 4 * (1 + size % 16); break;
      case 2: r.length = size % 16; break;
      default: r.length = std::min<unsigned>(max_length, 4u * (size % 64)); break;
    }
    r.streaming_width = (kind & 0x10) ? in.u8() % (r.length + 1) : r.length;
    if (kind & 0x20) {
      r.with_enables = true;
      const unsigned count = in.u8() % 6;  // 0: a pointer with length 0
      for (unsigned i = 0; i < count; ++i) r.enables.push_back((in.u8() & 1) ? TLM_BYTE_ENABLED : 0);
    }
    // Data: small values (the interesting ranges) or raw words.
    r.data.resize(r.length);
    for (unsigned i = 0; i + 4 <= r.length; i += 4) {
      const std::uint8_t shape = in.u8();
      std::uint32_t value;
      switch (shape & 3) {
        case 0: value = shape >> 2; break;                   // 0..63: CONTROL, N, RGB
        case 1: value = 65536 + (shape >> 2) - 32; break;    // around cos = 1.0
        case 2: value = in.u16(); break;
        default: value = in.u32(); break;
      }
      std::memcpy(&r.data[i], &value, 4);
    }
    for (unsigned i = r.length & ~3u; i < r.length; ++i) r.data[i] = in.u8();
    return r;
  }

  struct Answer {
    tlm::tlm_response_status response = tlm::TLM_INCOMPLETE_RESPONSE;
    unsigned debug_bytes = 0;
    std::vector<unsigned char> data;
    std::uint32_t status = 0;
  };

  Answer send(tlm_utils::simple_initiator_socket<Bench, 32>& socket, const Request& r) {
    Answer a;
    a.data = r.data;
    std::vector<unsigned char> enables = r.enables;
    if (enables.empty()) enables.push_back(0);  // a valid pointer for "length 0"
    tlm::tlm_generic_payload tx;
    tx.set_command(r.command);
    tx.set_address(r.address);
    tx.set_data_ptr(a.data.empty() ? nullptr : a.data.data());
    tx.set_data_length(r.length);
    tx.set_streaming_width(r.streaming_width);
    if (r.with_enables) {
      tx.set_byte_enable_ptr(enables.data());
      tx.set_byte_enable_length(static_cast<unsigned>(r.enables.size()));
    }
    tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    if (r.debug) {
      if (r.command == tlm::TLM_READ_COMMAND || r.command == tlm::TLM_WRITE_COMMAND)
        a.debug_bytes = socket->transport_dbg(tx);
      a.response = tlm::TLM_OK_RESPONSE;
    } else {
      sc_time delay = sc_core::SC_ZERO_TIME;
      socket->b_transport(tx, delay);
      wait(delay);
      a.response = tx.get_response_status();
    }
    std::uint32_t status = 0;
    tlm::tlm_generic_payload read;
    read.set_command(tlm::TLM_READ_COMMAND);
    read.set_address(offset_of(Reg::status));
    read.set_data_ptr(reinterpret_cast<unsigned char*>(&status));
    read.set_data_length(4);
    read.set_streaming_width(4);
    sc_time delay = sc_core::SC_ZERO_TIME;
    socket->b_transport(read, delay);
    if (read.get_response_status() != tlm::TLM_OK_RESPONSE) finding("STATUS read refused");
    a.status = status;
    return a;
  }

  void replay(Bytes in) {
    for (std::size_t t = 0; t < max_transactions && !in.empty(); ++t) {
      const Request r = decode(in);
      const Answer from_lt = send(to_lt, r);
      const Answer from_pin = send(to_pin, r);
      const std::string what = "transaction " + std::to_string(t) + " (command " +
                               std::to_string(r.command) + ", address " +
                               std::to_string(r.address) + ", length " + std::to_string(r.length) + ")";
      if (from_lt.response != from_pin.response)
        finding(what + ": lt answered " + std::to_string(from_lt.response) + ", pin " +
                std::to_string(from_pin.response));
      if (from_lt.debug_bytes != from_pin.debug_bytes) finding(what + ": debug byte counts differ");
      if (from_lt.data != from_pin.data) finding(what + ": lt and pin data differ");
      if (from_lt.status != from_pin.status) finding(what + ": STATUS differs");
      if (from_lt.status & status_bits::busy) finding(what + ": busy after the transaction ended");
      if (!r.debug && from_lt.response != tlm::TLM_OK_RESPONSE) {
        const auto cause = static_cast<ErrorCause>((from_lt.status & status_bits::cause_mask) >>
                                                   status_bits::cause_shift);
        if (!(from_lt.status & status_bits::error) || !cause_matches(from_lt.response, cause))
          finding(what + ": refusal " + std::to_string(from_lt.response) + " left cause " +
                  to_string(cause));
      }
    }
  }

  sc_core::sc_event go_;
  const std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
};

Bench* bench = nullptr;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  // The transactor drives the pins by the protocol: any protocol report is a finding.
  for (const char* type : report::protocol_types)
    sc_core::sc_report_handler::set_actions(type, sc_core::SC_DISPLAY | sc_core::SC_ABORT);
  bench = new Bench("bench");  // lives until exit, as SystemC wants
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return -1;
  bench->start(data, size);
  sc_core::sc_start();  // until the initiator's sc_pause()
  return 0;
}
