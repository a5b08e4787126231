// Misuse of the TLM-2.0 target (docs/misuse.md, "TLM"): every error response, with the
// STATUS cause and ERROR_ADDRESS it leaves, for both implementations behind the
// socket (lt, pin, and axi: the RTL IP behind its AXI4-Lite transactor). Expected responses come from the register map's documentation (target.h,
// docs/tlm.md), results from the double reference.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "specular/core.h"
#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "specular/twin/axi_target.h"
#include "support/protocol_bench.h"

namespace specular {
namespace {

using sc_core::sc_time;
using sc_core::SC_NS;
using tlm::tlm_response_status;

enum class Kind { lt, pin, axi };

/// An initiator with raw access to every field of the generic payload; the scenario
/// runs in an SC_THREAD (a second, optional thread plays another bus master).
class Initiator : public sc_core::sc_module {
 public:
  using Scenario = std::function<void(Initiator&)>;

  tlm_utils::simple_initiator_socket<Initiator, 32> socket{"socket"};

  Initiator(sc_core::sc_module_name name, Scenario main, Scenario second)
      : sc_module(name), main_(std::move(main)), second_(std::move(second)) {
    SPECULAR_HAS_PROCESS(Initiator);
    SC_THREAD(run_main);
    SC_THREAD(run_second);
  }

  struct Access {
    tlm::tlm_command command = tlm::TLM_READ_COMMAND;
    std::uint64_t address = 0;
    unsigned length = 4;
    unsigned streaming_width = 0;          ///< 0: equal to length (no streaming)
    std::vector<unsigned char> enables;    ///< empty: no byte-enable array
    bool enables_pointer_only = false;     ///< a byte-enable pointer with length 0
  };

  /// One b_transport; `data` must hold `access.length` bytes.
  tlm_response_status transport(const Access& access, unsigned char* data) {
    tlm::tlm_generic_payload tx;
    tx.set_command(access.command);
    tx.set_address(access.address);
    tx.set_data_ptr(data);
    tx.set_data_length(access.length);
    tx.set_streaming_width(access.streaming_width == 0 ? access.length : access.streaming_width);
    std::vector<unsigned char> enables = access.enables;
    if (!enables.empty() || access.enables_pointer_only) {
      if (enables.empty()) enables.push_back(TLM_BYTE_ENABLED);
      tx.set_byte_enable_ptr(enables.data());
      tx.set_byte_enable_length(access.enables_pointer_only ? 0 : static_cast<unsigned>(enables.size()));
    }
    tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_time delay = sc_core::SC_ZERO_TIME;
    socket->b_transport(tx, delay);
    wait(delay);  // no temporal decoupling here: simulated time follows the bus
    return tx.get_response_status();
  }
  tlm_response_status write(std::uint64_t address, std::uint32_t value) {
    Access a;
    a.command = tlm::TLM_WRITE_COMMAND;
    a.address = address;
    return transport(a, reinterpret_cast<unsigned char*>(&value));
  }
  tlm_response_status write(Reg reg, std::uint32_t value) { return write(offset_of(reg), value); }
  std::uint32_t read(Reg reg) {
    std::uint32_t value = 0xDEADBEEF;
    Access a;
    a.address = offset_of(reg);
    EXPECT_EQ(transport(a, reinterpret_cast<unsigned char*>(&value)), tlm::TLM_OK_RESPONSE)
        << info(reg).name;
    return value;
  }
  std::uint32_t status() { return read(Reg::status); }
  std::uint32_t cause() { return (status() & status_bits::cause_mask) >> status_bits::cause_shift; }
  /// Clears STATUS.error (W1C), as the driver's software would after handling it.
  void clear_error() { EXPECT_EQ(write(Reg::status, status_bits::error), tlm::TLM_OK_RESPONSE); }

 private:
  void run_main() {
    main_(*this);
    main_done_ = true;
    if (second_done_) sc_core::sc_stop();
  }
  void run_second() {
    if (second_) second_(*this);
    second_done_ = true;
    if (main_done_) sc_core::sc_stop();
  }
  Scenario main_, second_;
  bool main_done_ = false, second_done_ = false;
};

/// The kind run() elaborated (one per test process).
Kind running = Kind::lt;

/// Elaborates target + initiator once (one per TEST) and runs the scenario(s).
void run(Kind kind, Initiator::Scenario main, Initiator::Scenario second = {},
         const Config& config = Config{}) {
  static std::unique_ptr<SpecularTarget> target;  // live until exit, as SystemC wants
  static std::unique_ptr<Initiator> initiator;
  static std::unique_ptr<sc_core::sc_signal<bool>> irq;
  const sc_time period(10, SC_NS);
  running = kind;
  if (kind == Kind::lt)
    target = std::make_unique<SpecularLtTarget>("target", config, period);
  else if (kind == Kind::pin)
    target = std::make_unique<SpecularPinTarget>("target", config, period);
  else
    target = std::make_unique<SpecularAxiTarget>("target", config, period);
  if (kind == Kind::pin) {  // the transactor's pins start from a reset, as a SoC's would
    auto* harness = &static_cast<SpecularPinTarget&>(*target).harness;
    main = [harness, scenario = std::move(main)](Initiator& i) {
      harness->pin29_reset_n.write(false);
      sc_core::wait(sc_time(1, SC_NS));
      harness->pin29_reset_n.write(true);
      scenario(i);
    };
  }
  initiator = std::make_unique<Initiator>("initiator", std::move(main), std::move(second));
  irq = std::make_unique<sc_core::sc_signal<bool>>("irq");
  initiator->socket.bind(target->socket);
  target->done_irq(*irq);
  sc_core::sc_start();
}

constexpr std::uint32_t cause_of(ErrorCause cause) { return static_cast<std::uint32_t>(cause); }

/// The refusal left by the last access: STATUS.error, its cause and ERROR_ADDRESS.
void expect_refused(Initiator& i, ErrorCause cause, std::uint32_t error_address,
                    const std::string& what) {
  const std::uint32_t status = i.status();
  EXPECT_TRUE(status & status_bits::error) << what;
  EXPECT_EQ((status & status_bits::cause_mask) >> status_bits::cause_shift, cause_of(cause))
      << what << ": cause " << to_string(cause) << " expected";
  EXPECT_EQ(i.read(Reg::error_address), error_address) << what;
  i.clear_error();
  EXPECT_EQ(i.status() & (status_bits::error | status_bits::cause_mask), 0u) << what << ": W1C";
  EXPECT_EQ(i.read(Reg::error_address), 0u) << what << ": cleared with the error";
}

/// A refusal of the payload's shape (length, alignment, streaming, byte enables,
/// command). On axi the transactor refuses it before the bus, as AXI4-Lite cannot carry
/// it: the response is lt's, and the RTL's STATUS stays clear (docs/rtl_ip.md).
void expect_shape_refused(Initiator& i, ErrorCause cause, std::uint32_t error_address,
                          const std::string& what) {
  if (running == Kind::axi) {
    EXPECT_FALSE(i.status() & status_bits::error) << what << ": refused before the bus";
    return;
  }
  expect_refused(i, cause, error_address, what);
}

/// axi has no batch windows (BATCH_CAPACITY 0, docs/decisions.md): the RTL answers
/// their offsets as holes, DECERR, cause address.
bool has_windows() { return running != Kind::axi; }

class MisuseTlm : public testing::TestWithParam<Kind> {};

std::string kind_name(const testing::TestParamInfo<Kind>& info) {
  return info.param == Kind::lt ? "lt" : info.param == Kind::pin ? "pin" : "axi";
}

// Holes of the register map (docs/misuse.md's address map), misaligned and
// beyond-the-map offsets.
TEST_P(MisuseTlm, AddressErrorForUnmappedMisalignedAndRunawayBursts) {
  run(GetParam(), [](Initiator& i) {
    for (const std::uint64_t address :
         {std::uint64_t{0x01C}, std::uint64_t{0x034}, std::uint64_t{0x04C}, std::uint64_t{0x074},
          std::uint64_t{0x098}, std::uint64_t{0x0AC}, std::uint64_t{0x0FC}, std::uint64_t{0x2000},
          std::uint64_t{0x7000}, std::uint64_t{0x8000},
          std::uint64_t{0xFFFFFFF0}, std::uint64_t{0x022}, std::uint64_t{0x001},
          std::uint64_t{0x1002}}) {
      std::uint32_t data = 0;
      for (const tlm::tlm_command command : {tlm::TLM_READ_COMMAND, tlm::TLM_WRITE_COMMAND}) {
        Initiator::Access a;
        a.command = command;
        a.address = address;
        EXPECT_EQ(i.transport(a, reinterpret_cast<unsigned char*>(&data)),
                  tlm::TLM_ADDRESS_ERROR_RESPONSE)
            << std::hex << address;
        const std::string what = "address " + std::to_string(address);
        const RegisterInfo* row = decode(address & ~std::uint64_t{3});
        const bool mapped = row != nullptr && (has_windows() || (row->reg != Reg::batch_cos &&
                                                                 row->reg != Reg::batch_out));
        if (address % 4 != 0 && mapped)  // misaligned
          expect_shape_refused(i, ErrorCause::address, static_cast<std::uint32_t>(address), what);
        else  // a hole, or beyond the map
          expect_refused(i, ErrorCause::address, static_cast<std::uint32_t>(address), what);
      }
    }
    // A burst that starts inside BATCH_COS (0x1000, 1024 words) and runs past its end:
    // ERROR_ADDRESS names the first unmapped byte, 0x2000.
    std::vector<std::uint32_t> words(2, 0);
    Initiator::Access a;
    a.command = tlm::TLM_WRITE_COMMAND;
    a.address = 0x1000 + 4 * 1023;
    a.length = 8;
    EXPECT_EQ(i.transport(a, reinterpret_cast<unsigned char*>(words.data())),
              tlm::TLM_ADDRESS_ERROR_RESPONSE);
    if (has_windows())
      expect_refused(i, ErrorCause::address, 0x2000, "runaway burst");
    else  // axi: the window is a hole, refused at the burst's first word
      expect_refused(i, ErrorCause::address, 0x1000 + 4 * 1023, "BATCH_COS, a hole on axi");
    EXPECT_FALSE(i.status() & status_bits::done) << "the refused burst computed nothing";
  });
}

// Oversized (8 bytes on a register off a doubleword offset), zero, odd lengths and streaming.
TEST_P(MisuseTlm, BurstErrorForBadLengthsAndStreaming) {
  run(GetParam(), [](Initiator& i) {
    std::vector<unsigned char> buffer(64, 0);
    struct Case {
      std::uint64_t address;
      unsigned length;
      unsigned streaming_width;
    };
    const Case cases[] = {
        {0x024, 8, 0},    // N: two words off a doubleword offset (a 64-bit access is 8-aligned)
        {0x020, 6, 0},    // COS: a word and a half
        {0x000, 0, 0},    // ID: nothing
        {0x000, 3, 0},    // ID: not a multiple of 4
        {0x040, 12, 0},   // OUT_R..OUT_B as one burst: single registers are not a window
        {0x1000, 6, 0},   // BATCH_COS: not whole words
        {0x1000, 16, 4},  // BATCH_COS: streaming (width 4 < length 16)
        {0x4000, 8, 4},   // BATCH_OUT: streaming
    };
    for (const Case& c : cases) {
      for (const tlm::tlm_command command : {tlm::TLM_READ_COMMAND, tlm::TLM_WRITE_COMMAND}) {
        Initiator::Access a;
        a.command = command;
        a.address = c.address;
        a.length = c.length;
        a.streaming_width = c.streaming_width;
        if (!has_windows() && c.address >= offset_of(Reg::batch_cos)) {  // axi: a hole
          EXPECT_EQ(i.transport(a, buffer.data()), tlm::TLM_ADDRESS_ERROR_RESPONSE) << std::hex << c.address;
          expect_refused(i, ErrorCause::address, static_cast<std::uint32_t>(c.address), "a window, a hole on axi");
          continue;
        }
        EXPECT_EQ(i.transport(a, buffer.data()), tlm::TLM_BURST_ERROR_RESPONSE)
            << std::hex << c.address << std::dec << " length " << c.length;
        expect_shape_refused(i, ErrorCause::burst, static_cast<std::uint32_t>(c.address), "burst");
      }
    }
    EXPECT_EQ(i.read(Reg::n), 1u) << "N keeps its reset value";
  });
}

TEST_P(MisuseTlm, ByteEnableErrorUnlessEveryByteIsEnabled) {
  run(GetParam(), [](Initiator& i) {
    ASSERT_EQ(i.write(Reg::n, 77), tlm::TLM_OK_RESPONSE);
    std::uint32_t value = 500;
    const std::vector<std::vector<unsigned char>> refused = {
        {0xFF, 0x00, 0xFF, 0xFF}, {0x00, 0x00, 0x00, 0x00}, {0xFF, 0xFF, 0x00}, {0x00}};
    for (const auto& enables : refused) {
      Initiator::Access a;
      a.command = tlm::TLM_WRITE_COMMAND;
      a.address = offset_of(Reg::n);
      a.enables = enables;
      EXPECT_EQ(i.transport(a, reinterpret_cast<unsigned char*>(&value)),
                tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
      expect_shape_refused(i, ErrorCause::byte_enable, offset_of(Reg::n), "byte enables");
    }
    Initiator::Access pointer_only;  // a byte-enable pointer whose length is 0
    pointer_only.command = tlm::TLM_WRITE_COMMAND;
    pointer_only.address = offset_of(Reg::n);
    pointer_only.enables_pointer_only = true;
    EXPECT_EQ(i.transport(pointer_only, reinterpret_cast<unsigned char*>(&value)),
              tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
    expect_shape_refused(i, ErrorCause::byte_enable, offset_of(Reg::n), "byte-enable length 0");
    EXPECT_EQ(i.read(Reg::n), 77u) << "no refused write changed N";

    Initiator::Access all;  // every byte enabled (a repeating 1-byte pattern): accepted
    all.command = tlm::TLM_WRITE_COMMAND;
    all.address = offset_of(Reg::n);
    all.enables = {0xFF};
    EXPECT_EQ(i.transport(all, reinterpret_cast<unsigned char*>(&value)), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(i.read(Reg::n), 500u);
  });
}

// Read-only rows (register map: RO) refuse writes; an unknown command is refused.
TEST_P(MisuseTlm, CommandErrorForWritesToReadOnlyRegistersAndUnknownCommands) {
  run(GetParam(), [](Initiator& i) {
    for (const Reg reg : {Reg::id, Reg::version, Reg::config, Reg::batch_capacity,
                          Reg::error_address, Reg::out_r, Reg::out_g, Reg::out_b, Reg::reg1,
                          Reg::reg9_pass1_lo, Reg::reg9_pass2_hi, Reg::rom38_k, Reg::norm39,
                          Reg::batch_out}) {
      if (reg == Reg::batch_out && !has_windows()) {  // a hole on axi
        EXPECT_EQ(i.write(reg, 0x12345678), tlm::TLM_ADDRESS_ERROR_RESPONSE);
        expect_refused(i, ErrorCause::address, offset_of(reg), "BATCH_OUT, a hole on axi");
        continue;
      }
      const std::uint32_t before = i.read(reg);
      EXPECT_EQ(i.write(reg, 0x12345678), tlm::TLM_COMMAND_ERROR_RESPONSE) << info(reg).name;
      expect_refused(i, ErrorCause::read_only, offset_of(reg), info(reg).name);
      EXPECT_EQ(i.read(reg), before) << info(reg).name << " unchanged";
    }
    EXPECT_EQ(i.read(Reg::id), 0x00059965u) << "the patent number, UA 59965 U";
    // tlm_command has read (0), write (1), ignore (2); 3 is none of them.
    std::uint32_t data = 0;
    Initiator::Access a;
    a.command = static_cast<tlm::tlm_command>(3);
    a.address = offset_of(Reg::n);
    EXPECT_EQ(i.transport(a, reinterpret_cast<unsigned char*>(&data)),
              tlm::TLM_COMMAND_ERROR_RESPONSE);
    expect_shape_refused(i, ErrorCause::command, offset_of(Reg::n), "command 3");
    // IGNORE is a legal command that does nothing.
    a.command = tlm::TLM_IGNORE_COMMAND;
    EXPECT_EQ(i.transport(a, reinterpret_cast<unsigned char*>(&data)), tlm::TLM_OK_RESPONSE);
    EXPECT_FALSE(i.status() & status_bits::error);
  });
}

// n outside 1..1000, cos above 1.0 (65536 in U1.16), R, G, B above 255, undefined
// CONTROL bits: refused, the register keeps its value — never clamped.
TEST_P(MisuseTlm, OutOfRangeValuesAreRefusedNeverClamped) {
  run(GetParam(), [](Initiator& i) {
    ASSERT_EQ(i.write(Reg::cos, 40000), tlm::TLM_OK_RESPONSE);
    ASSERT_EQ(i.write(Reg::n, 321), tlm::TLM_OK_RESPONSE);
    ASSERT_EQ(i.write(Reg::r, 11), tlm::TLM_OK_RESPONSE);
    ASSERT_EQ(i.write(Reg::g, 22), tlm::TLM_OK_RESPONSE);
    ASSERT_EQ(i.write(Reg::b, 33), tlm::TLM_OK_RESPONSE);
    struct Case {
      Reg reg;
      std::uint32_t value;
      ErrorCause cause;
      std::uint32_t kept;
    };
    const Case cases[] = {
        {Reg::cos, 65537, ErrorCause::cos_out_of_range, 40000},
        {Reg::cos, 0xFFFFFFFF, ErrorCause::cos_out_of_range, 40000},
        {Reg::n, 0, ErrorCause::n_out_of_range, 321},
        {Reg::n, 1001, ErrorCause::n_out_of_range, 321},
        {Reg::n, 0x80000001, ErrorCause::n_out_of_range, 321},
        {Reg::r, 256, ErrorCause::rgb_out_of_range, 11},
        {Reg::g, 0xFFFFFFFF, ErrorCause::rgb_out_of_range, 22},
        {Reg::b, 1000, ErrorCause::rgb_out_of_range, 33},
    };
    for (const Case& c : cases) {
      EXPECT_EQ(i.write(c.reg, c.value), tlm::TLM_GENERIC_ERROR_RESPONSE)
          << info(c.reg).name << " = " << c.value;
      expect_refused(i, c.cause, offset_of(c.reg), info(c.reg).name);
      EXPECT_EQ(i.read(c.reg), c.kept) << info(c.reg).name << " kept its value";
    }
    // The limits themselves are legal.
    EXPECT_EQ(i.write(Reg::cos, 65536), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(i.write(Reg::n, 1000), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(i.write(Reg::n, 1), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(i.write(Reg::b, 255), tlm::TLM_OK_RESPONSE);

    for (const std::uint32_t control : {0x2u, 0x80000000u, 0x3u}) {
      EXPECT_EQ(i.write(Reg::control, control), tlm::TLM_GENERIC_ERROR_RESPONSE) << control;
      expect_refused(i, ErrorCause::reserved_bits, offset_of(Reg::control), "CONTROL");
      EXPECT_FALSE(i.status() & status_bits::done) << "a refused START runs nothing";
    }

    // A batch with one bad word is refused whole: ERROR_ADDRESS names the word.
    const std::uint32_t batch[4] = {0, 65536, 70000, 3};
    Initiator::Access a;
    a.command = tlm::TLM_WRITE_COMMAND;
    a.address = offset_of(Reg::batch_cos);
    a.length = sizeof batch;
    if (!has_windows()) {  // axi: the window is a hole, refused at its first word
      EXPECT_EQ(i.transport(a, reinterpret_cast<unsigned char*>(const_cast<std::uint32_t*>(batch))),
                tlm::TLM_ADDRESS_ERROR_RESPONSE);
      expect_refused(i, ErrorCause::address, offset_of(Reg::batch_cos), "BATCH_COS, a hole on axi");
      return;
    }
    EXPECT_EQ(i.transport(a, reinterpret_cast<unsigned char*>(const_cast<std::uint32_t*>(batch))),
              tlm::TLM_GENERIC_ERROR_RESPONSE);
    expect_refused(i, ErrorCause::cos_out_of_range, offset_of(Reg::batch_cos) + 8, "BATCH_COS");
    EXPECT_FALSE(i.status() & status_bits::done);
    std::uint32_t stored[4] = {1, 1, 1, 1};
    a.command = tlm::TLM_READ_COMMAND;
    EXPECT_EQ(i.transport(a, reinterpret_cast<unsigned char*>(stored)), tlm::TLM_OK_RESPONSE);
    for (const std::uint32_t word : stored) EXPECT_EQ(word, 0u) << "nothing of the batch stored";
  });
}

// The same refusals through the debug interface: transport_dbg stops at the first
// word it cannot access and says how many bytes it did.
TEST_P(MisuseTlm, DebugTransportStopsAtTheFirstBadWord) {
  run(GetParam(), [](Initiator& i) {
    ASSERT_EQ(i.write(Reg::n, 5), tlm::TLM_OK_RESPONSE);
    auto debug = [&](tlm::tlm_command command, std::uint64_t address, std::uint32_t* data,
                     unsigned length) {
      tlm::tlm_generic_payload tx;
      tx.set_command(command);
      tx.set_address(address);
      tx.set_data_ptr(reinterpret_cast<unsigned char*>(data));
      tx.set_data_length(length);
      return i.socket->transport_dbg(tx);
    };
    std::uint32_t words[4] = {0, 0, 0, 0};
    EXPECT_EQ(debug(tlm::TLM_READ_COMMAND, 0x022, words, 4), 0u) << "misaligned";
    EXPECT_EQ(debug(tlm::TLM_READ_COMMAND, 0x020, words, 6), 0u) << "not whole words";
    EXPECT_EQ(debug(tlm::TLM_READ_COMMAND, 0x018, words, 16), 4u) << "0x01C is a hole";
    std::uint32_t bad_n[2] = {7, 1001};  // N = 7 accepted, then R = 1001 refused
    // axi refuses every debug write (a debugger's write has no AXI4-Lite form without
    // side effects): 0 bytes, N untouched.
    const bool debug_writes = running != Kind::axi;
    EXPECT_EQ(debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::n), bad_n, 8), debug_writes ? 4u : 0u);
    std::uint32_t id_write = 1;
    EXPECT_EQ(debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::id), &id_write, 4), 0u) << "read-only";
    EXPECT_EQ(i.read(Reg::n), debug_writes ? 7u : 5u);
    EXPECT_EQ(i.read(Reg::r), 0u);
    EXPECT_FALSE(i.status() & status_bits::error) << "debug accesses never set STATUS.error";
  });
}

// START while an operation is in flight: only the pin transactor takes simulated
// time, so only there can a second master's START meet a busy device. It is not
// misuse (issue 20: any legal TLM use): the second master sees STATUS.busy, its START,
// operand write and batch wait their turn and then succeed, and the first operation's
// result is intact. The lt target completes each START within its b_transport, so it
// is never busy.
TEST_P(MisuseTlm, StartWhileBusyWaitsItsTurnAndTheRunningOperationIsIntact) {
  if (GetParam() == Kind::axi)
    GTEST_SKIP() << "axi, as lt, completes each START inside its b_transport (never busy), and "
                    "its register accesses take bus cycles, so this scenario's timing (the first "
                    "master's writes done before the second wakes) does not hold there";
  const Config config;
  const Operands op = Core(config).operands(0.95, 40, 200, 100, 50);
  const Operands other = Core(config).operands(0.5, 3, 1, 2, 3);
  Result got;
  std::vector<tlm_response_status> second_responses;
  std::uint32_t second_status = 0;
  std::uint32_t busy_seen = 0;
  run(
      GetParam(),
      [&](Initiator& i) {
        ASSERT_EQ(i.write(Reg::n, static_cast<std::uint32_t>(op.n)), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write(Reg::r, static_cast<std::uint32_t>(op.rgb[0])), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write(Reg::g, static_cast<std::uint32_t>(op.rgb[1])), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write(Reg::b, static_cast<std::uint32_t>(op.rgb[2])), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(i.write(Reg::cos, static_cast<std::uint32_t>(op.cos)), tlm::TLM_OK_RESPONSE);
        sc_core::wait(sc_time(100, SC_NS));  // the second master is waiting for this moment
        EXPECT_EQ(i.write(Reg::control, control_bits::start), tlm::TLM_OK_RESPONSE);
        got.norm39 = static_cast<std::int32_t>(i.read(Reg::norm39));
        for (int ch = 0; ch < 3; ++ch)
          got.out[ch] = static_cast<std::int32_t>(i.read(static_cast<Reg>(index_of(Reg::out_r) + ch)));
      },
      [&](Initiator& i) {
        sc_core::wait(sc_time(110, SC_NS));  // one clock period after the first START
        busy_seen = i.status() & status_bits::busy;
        second_responses.push_back(i.write(Reg::control, control_bits::start));
        second_responses.push_back(i.write(Reg::n, 7));  // operands hold until done (§3)
        const std::uint32_t batch[2] = {static_cast<std::uint32_t>(other.cos), 0};
        Initiator::Access a;
        a.command = tlm::TLM_WRITE_COMMAND;
        a.address = offset_of(Reg::batch_cos);
        a.length = 8;
        second_responses.push_back(
            i.transport(a, reinterpret_cast<unsigned char*>(const_cast<std::uint32_t*>(batch))));
        second_status = i.status();
      },
      config);
  protocol_testing::expect_matches_reference(config, op, got);
  ASSERT_EQ(second_responses.size(), 3u);
  if (GetParam() == Kind::pin)
    EXPECT_TRUE(busy_seen) << "STATUS.busy during the pin transactor's operation";
  else
    EXPECT_FALSE(busy_seen) << "lt: each operation completes inside b_transport";
  EXPECT_EQ(second_responses[0], tlm::TLM_OK_RESPONSE) << "START while busy waits its turn";
  EXPECT_EQ(second_responses[1], tlm::TLM_OK_RESPONSE) << "N written after that operation";
  EXPECT_EQ(second_responses[2], tlm::TLM_OK_RESPONSE) << "BATCH_COS after that";
  EXPECT_FALSE(second_status & status_bits::error);
  // Whatever the second master did, no protocol misuse reached the pins.
  EXPECT_EQ(protocol_testing::protocol_reports(), 0);
}

INSTANTIATE_TEST_SUITE_P(BothTargets, MisuseTlm, testing::Values(Kind::lt, Kind::pin, Kind::axi), kind_name);

// A target counts its latencies in clock periods: a zero period would make every
// annotated delay zero, so construction refuses it and names the value (issue 37: the
// one line of the constructor no test reached).
// Every bus a register holds must fit its 32 bits: pins 24-26 widened to S18.14 are
// 1 + 18 + 14 = 33 bits, and construction refuses them naming the format and its width.
TEST(MisuseTlmConstruction, AFormatWiderThanItsRegisterIsRefusedNamingIt) {
  Config config;
  config.widths.out_frac_bits = 14;
  try {
    SpecularLtTarget target("target", config);
    FAIL() << "a 33-bit OUT format was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("OUT format"), std::string::npos) << what;
    EXPECT_NE(what.find("is 33 bits wide"), std::string::npos) << what;
    EXPECT_NE(what.find("TLM target"), std::string::npos) << what;
  }
}

// ROM38_K too (a C++ mutant deleted its check and no test noticed): U16.17 is 33 bits.
// COS, N and RGB cannot be: Widths::validate caps them at 31, 16 and 16 bits first.
TEST(MisuseTlmConstruction, ARom38FormatWiderThanItsRegisterIsRefusedNamingIt) {
  Config config;
  config.widths.rom38_int_bits = 16;
  config.widths.rom38_frac_bits = 17;
  try {
    SpecularLtTarget target("target", config);
    FAIL() << "a 33-bit ROM38_K format was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("ROM38_K format"), std::string::npos) << what;
    EXPECT_NE(what.find("is 33 bits wide"), std::string::npos) << what;
  }
}

TEST(MisuseTlmConstruction, ANorm39FormatWiderThanItsRegisterIsRefusedNamingIt) {
  // Multiplier 39's output S10.22: 1 + 10 + 22 = 33 bits, one more than NORM39 holds.
  Config config;
  config.widths.norm_frac_bits = 22;
  try {
    SpecularLtTarget target("target", config);
    FAIL() << "a 33-bit NORM39 format was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("NORM39 format"), std::string::npos) << what;
    EXPECT_NE(what.find("is 33 bits wide"), std::string::npos) << what;
  }
}

TEST(MisuseTlmConstruction, AClockPeriodOfZeroIsRefusedNamingIt) {
  try {
    SpecularLtTarget target("target", Config{}, sc_core::SC_ZERO_TIME);
    FAIL() << "a zero clock period was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("clock period 0 s"), std::string::npos) << what;
    EXPECT_NE(what.find("must be positive"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace specular
