// The diagnostics of the TLM side that the device's own targets never provoke (issue 37:
// the lines of driver.cpp and target.cpp no other test reached):
// - response_name() names every TLM-2.0 response status as IEEE 1666 spells it;
// - SpecularDriver names a status no target of ours answers (TLM_INCOMPLETE_RESPONSE: a
//   target that never set it) and says so when STATUS cannot be read to tell why;
// - SpecularTarget's busy guard: a target whose execute() takes simulated time and does
//   not serialise accesses (the contract in target.h leaves that to the derived class)
//   refuses every write that would change an operand or start an operation while one
//   runs, with STATUS cause busy, and leaves the running operation's operands alone;
// - a refused TLM_IGNORE_COMMAND is reported as "ignore";
// - a byte-enable array longer than the data counts only as far as the data.
// Expected values are the standard's names, the register map's offsets and causes, and
// the operands written: nothing read back from the code under test.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "specular/core.h"
#include "specular/report_ids.h"
#include "specular/systemc.h"
#include "specular/tlm/driver.h"
#include "specular/tlm/lt_target.h"
#include "specular/tlm/response_name.h"
#include "specular/tlm/target.h"

namespace specular {
namespace {

using sc_core::sc_time;
using sc_core::SC_NS;

/// One b_transport through `socket` with every payload field set, from a thread; the
/// annotated delay is waited out. Returns the target's response.
template <class Socket>
tlm::tlm_response_status transport(Socket& socket, tlm::tlm_command command, std::uint64_t address,
                                   void* data, unsigned length, unsigned char* enables = nullptr,
                                   unsigned enables_length = 0) {
  tlm::tlm_generic_payload tx;
  tx.set_command(command);
  tx.set_address(address);
  tx.set_data_ptr(static_cast<unsigned char*>(data));
  tx.set_data_length(length);
  tx.set_streaming_width(length);
  tx.set_byte_enable_ptr(enables);
  tx.set_byte_enable_length(enables_length);
  tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  sc_time delay = sc_core::SC_ZERO_TIME;
  socket->b_transport(tx, delay);
  sc_core::wait(delay);
  return tx.get_response_status();
}

/// The messages of the target's refusal reports (/specular/tlm/access-refused), collected
/// instead of printed: one test per process, so one handler per process.
const std::vector<std::string>& capture_refusal_reports() {
  static std::vector<std::string> reports;
  sc_core::sc_report_handler::set_handler(
      [](const sc_core::sc_report& report, const sc_core::sc_actions&) {
        if (std::string(report.get_msg_type()) == report::tlm_access_refused)
          reports.push_back(report.get_msg());
      });
  return reports;
}

TEST(ResponseName, NamesEveryStatusAsTheStandardSpellsIt) {
  EXPECT_STREQ(response_name(tlm::TLM_OK_RESPONSE), "TLM_OK_RESPONSE");
  EXPECT_STREQ(response_name(tlm::TLM_INCOMPLETE_RESPONSE), "TLM_INCOMPLETE_RESPONSE");
  EXPECT_STREQ(response_name(tlm::TLM_GENERIC_ERROR_RESPONSE), "TLM_GENERIC_ERROR_RESPONSE");
  EXPECT_STREQ(response_name(tlm::TLM_ADDRESS_ERROR_RESPONSE), "TLM_ADDRESS_ERROR_RESPONSE");
  EXPECT_STREQ(response_name(tlm::TLM_COMMAND_ERROR_RESPONSE), "TLM_COMMAND_ERROR_RESPONSE");
  EXPECT_STREQ(response_name(tlm::TLM_BURST_ERROR_RESPONSE), "TLM_BURST_ERROR_RESPONSE");
  EXPECT_STREQ(response_name(tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE), "TLM_BYTE_ENABLE_ERROR_RESPONSE");
}

// ---- SpecularDriver against a target that answers as scripted ------------------------

/// Answers every access with `answer`, except a read of STATUS, which returns
/// `status_word` (or TLM_ADDRESS_ERROR_RESPONSE when `status_readable` is false).
class ScriptedTarget : public sc_core::sc_module {
 public:
  explicit ScriptedTarget(sc_core::sc_module_name name) : sc_module(name) {
    socket.register_b_transport(this, &ScriptedTarget::b_transport);
  }
  tlm_utils::simple_target_socket<ScriptedTarget, 32> socket{"socket"};
  tlm::tlm_response_status answer = tlm::TLM_OK_RESPONSE;
  bool status_readable = true;
  std::uint32_t status_word = 0;

 private:
  void b_transport(tlm::tlm_generic_payload& tx, sc_time&) {
    if (tx.is_read() && tx.get_address() == offset_of(Reg::status)) {
      if (!status_readable) return tx.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
      std::memcpy(tx.get_data_ptr(), &status_word, 4);
      return tx.set_response_status(tlm::TLM_OK_RESPONSE);
    }
    tx.set_response_status(answer);
  }
};

/// A driver bound to a ScriptedTarget; `scenario` runs in a thread of its own.
class DriverBench : public sc_core::sc_module {
 public:
  DriverBench(sc_core::sc_module_name name, std::function<void(DriverBench&)> scenario)
      : sc_module(name), driver(socket, 0, keeper), scenario_(std::move(scenario)) {
    SPECULAR_HAS_PROCESS(DriverBench);
    socket.bind(target.socket);
    SC_THREAD(run);
  }
  tlm_utils::simple_initiator_socket<DriverBench, 32> socket{"socket"};
  ScriptedTarget target{"target"};
  tlm_utils::tlm_quantumkeeper keeper;
  SpecularDriver driver;

 private:
  void run() { scenario_(*this); }
  std::function<void(DriverBench&)> scenario_;
};

/// The message of the TransportError that writing N throws (empty if none is thrown).
std::string refusal_of_write(DriverBench& b, tlm::tlm_response_status* status = nullptr) {
  try {
    b.driver.write(Reg::n, 5);
  } catch (const TransportError& error) {
    if (status != nullptr) *status = error.status();
    return error.what();
  }
  return "";
}

TEST(DriverDiagnostics, NamesAnIncompleteResponseAndAnUnreadableStatus) {
  std::string incomplete, unreadable;
  tlm::tlm_response_status incomplete_status = tlm::TLM_OK_RESPONSE;
  DriverBench bench("bench", [&](DriverBench& b) {
    // A target that never sets the status leaves the driver's TLM_INCOMPLETE_RESPONSE.
    b.target.answer = tlm::TLM_INCOMPLETE_RESPONSE;
    b.target.status_word = static_cast<std::uint32_t>(ErrorCause::n_out_of_range)
                           << status_bits::cause_shift;
    incomplete = refusal_of_write(b, &incomplete_status);
    b.target.answer = tlm::TLM_GENERIC_ERROR_RESPONSE;
    b.target.status_readable = false;
    unreadable = refusal_of_write(b);
  });
  sc_core::sc_start();
  EXPECT_EQ(incomplete_status, tlm::TLM_INCOMPLETE_RESPONSE);
  EXPECT_NE(incomplete.find("write to N (offset 0x"), std::string::npos) << incomplete;
  EXPECT_NE(incomplete.find("refused: TLM_INCOMPLETE_RESPONSE"), std::string::npos) << incomplete;
  EXPECT_NE(incomplete.find("STATUS cause n_out_of_range"), std::string::npos) << incomplete;
  EXPECT_NE(unreadable.find("refused: TLM_GENERIC_ERROR_RESPONSE"), std::string::npos) << unreadable;
  EXPECT_NE(unreadable.find("STATUS could not be read to tell why"), std::string::npos) << unreadable;
  EXPECT_EQ(unreadable.find("STATUS cause"), std::string::npos) << unreadable;
}

// ---- SpecularTarget's busy guard ------------------------------------------------------

/// A target whose operation takes simulated time inside b_transport (it waits its
/// latency) and that does not serialise accesses: exactly what target.h says a derived
/// target must guard against, so the base class's busy refusals are what a second
/// master meets.
class WaitingTarget : public SpecularTarget {
 public:
  WaitingTarget(sc_core::sc_module_name name, const sc_time& period)
      : SpecularTarget(name, Config{}, period), core_(Config{}) {}

 private:
  void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
               std::uint32_t* out, Result& last, sc_time& delay) override {
    sc_core::wait(delay + clock_period() * latency_cycles(count));
    delay = sc_core::SC_ZERO_TIME;
    Operands op = shared;
    for (std::size_t i = 0; i < count; ++i) {
      op.cos = cos[i];
      last = core_.run(op);
      for (int ch = 0; ch < 3; ++ch) out[3 * i + ch] = static_cast<std::uint32_t>(last.out[ch]);
    }
  }
  Core core_;
};

/// Two masters on one WaitingTarget (a router's job done by two sockets' worth of
/// b_transport calls into the same target socket, from two threads).
class TwoMasters : public sc_core::sc_module {
 public:
  using Scenario = std::function<void(TwoMasters&)>;
  TwoMasters(sc_core::sc_module_name name, Scenario first, Scenario second)
      : sc_module(name), first_(std::move(first)), second_(std::move(second)) {
    SPECULAR_HAS_PROCESS(TwoMasters);
    socket.bind(target.socket);
    SC_THREAD(run_first);
    SC_THREAD(run_second);
  }
  tlm_utils::simple_initiator_socket<TwoMasters, 32> socket{"socket"};
  WaitingTarget target{"target", sc_time(10, SC_NS)};

  tlm::tlm_response_status access(tlm::tlm_command command, std::uint64_t address, void* data,
                                  unsigned length) {
    return transport(socket, command, address, data, length);
  }
  tlm::tlm_response_status write(std::uint64_t address, std::uint32_t value) {
    return access(tlm::TLM_WRITE_COMMAND, address, &value, 4);
  }
  std::uint32_t read(Reg reg) {
    std::uint32_t value = 0xDEADBEEF;
    EXPECT_EQ(access(tlm::TLM_READ_COMMAND, offset_of(reg), &value, 4), tlm::TLM_OK_RESPONSE);
    return value;
  }

 private:
  void run_first() { first_(*this); }
  void run_second() { second_(*this); }
  Scenario first_, second_;
};

/// What the second master saw of one refused write.
struct Refusal {
  std::string what;
  tlm::tlm_response_status response;
  std::uint32_t status;
  std::uint32_t error_address;
};

TEST(TargetBusyGuard, AWriteWhileAnOperationRunsIsRefusedAsBusy) {
  constexpr std::uint32_t cos = 50000, n = 40, r = 200, g = 100, b = 50;
  // 8 bytes at a doubleword offset cover two registers, vetted lower offset first
  // (docs/integration.md): COS and N, and CONTROL with the read-only BATCH_CAPACITY, where
  // START's busy verdict comes before the read-only one.
  static_assert(offset_of(Reg::cos) % 8 == 0 && offset_of(Reg::n) == offset_of(Reg::cos) + 4);
  static_assert(offset_of(Reg::control) % 8 == 0 &&
                offset_of(Reg::batch_capacity) == offset_of(Reg::control) + 4);
  std::vector<Refusal> refusals;
  std::vector<tlm::tlm_response_status> clears;  // STATUS's W1C is no operand write: never busy
  std::uint32_t busy_status = 0, after[5] = {};
  const auto refused = [&](TwoMasters& m, const std::string& what, std::uint64_t address,
                           const std::vector<std::uint32_t>& words) {
    std::vector<std::uint32_t> data = words;
    const tlm::tlm_response_status response =
        m.access(tlm::TLM_WRITE_COMMAND, address, data.data(), static_cast<unsigned>(4 * data.size()));
    refusals.push_back({what, response, m.read(Reg::status), m.read(Reg::error_address)});
    clears.push_back(m.write(offset_of(Reg::status), status_bits::error));  // clear, so the next is seen alone
  };
  TwoMasters masters(
      "masters",
      [&](TwoMasters& m) {
        for (auto [reg, value] : {std::pair{Reg::n, n}, {Reg::r, r}, {Reg::g, g}, {Reg::b, b}, {Reg::cos, cos}})
          ASSERT_EQ(m.write(offset_of(reg), value), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(m.write(offset_of(Reg::control), control_bits::start), tlm::TLM_OK_RESPONSE);
      },
      [&](TwoMasters& m) {
        sc_core::wait(sc_time(5, SC_NS));  // the first master's START is running (25 ns)
        busy_status = m.read(Reg::status);
        refused(m, "CONTROL.START", offset_of(Reg::control), {control_bits::start});
        refused(m, "N", offset_of(Reg::n), {7});
        refused(m, "OPERANDS", offset_of(Reg::operands), {1000, 3, 1, 2, 3, 0});
        refused(m, "BATCH_COS", offset_of(Reg::batch_cos), {1000, 2000});
        refused(m, "8 bytes: COS, N", offset_of(Reg::cos), {cos, n});
        refused(m, "8 bytes: CONTROL, BATCH_CAPACITY", offset_of(Reg::control), {control_bits::start, 0});
        // CONTROL without START is no action, so not busy: the read-only word refuses it.
        refused(m, "8 bytes: CONTROL 0, BATCH_CAPACITY", offset_of(Reg::control), {0, 0});
        sc_core::wait(sc_time(100, SC_NS));  // long after the operation
        int i = 0;
        for (Reg reg : {Reg::cos, Reg::n, Reg::r, Reg::g, Reg::b}) after[i++] = m.read(reg);
      });
  sc_core::sc_start();

  EXPECT_TRUE(busy_status & status_bits::busy) << "the operation runs while the second master looks";
  const std::uint32_t busy_cause = static_cast<std::uint32_t>(ErrorCause::busy) << status_bits::cause_shift;
  const std::uint32_t read_only_cause = static_cast<std::uint32_t>(ErrorCause::read_only)
                                        << status_bits::cause_shift;
  const std::uint64_t addresses[] = {offset_of(Reg::control), offset_of(Reg::n), offset_of(Reg::operands),
                                     offset_of(Reg::batch_cos), offset_of(Reg::cos),
                                     offset_of(Reg::control), offset_of(Reg::batch_capacity)};
  ASSERT_EQ(refusals.size(), 7u);
  for (std::size_t k = 0; k < refusals.size(); ++k) {
    const Refusal& f = refusals[k];
    const bool busy = k < 6;
    EXPECT_EQ(f.response, busy ? tlm::TLM_GENERIC_ERROR_RESPONSE : tlm::TLM_COMMAND_ERROR_RESPONSE) << f.what;
    EXPECT_TRUE(f.status & status_bits::error) << f.what;
    EXPECT_EQ(f.status & status_bits::cause_mask, busy ? busy_cause : read_only_cause) << f.what;
    EXPECT_EQ(f.error_address, addresses[k]) << f.what;
  }
  ASSERT_EQ(clears.size(), 7u);
  for (tlm::tlm_response_status clear : clears)
    EXPECT_EQ(clear, tlm::TLM_OK_RESPONSE) << "writing STATUS (W1C) during the operation (docs/tlm/registers.md cause 6)";
  // Nothing the second master wrote reached the operand registers.
  const std::uint32_t written[5] = {cos, n, r, g, b};
  for (int k = 0; k < 5; ++k) EXPECT_EQ(after[k], written[k]) << "operand register " << k;
}

// ---- a refused ignore command ---------------------------------------------------------

/// An initiator thread for one SpecularLtTarget.
class LtBench : public sc_core::sc_module {
 public:
  LtBench(sc_core::sc_module_name name, std::function<void(LtBench&)> scenario)
      : sc_module(name), scenario_(std::move(scenario)) {
    SPECULAR_HAS_PROCESS(LtBench);
    socket.bind(target.socket);
    SC_THREAD(run);
  }
  tlm_utils::simple_initiator_socket<LtBench, 32> socket{"socket"};
  SpecularLtTarget target{"target"};

 private:
  void run() { scenario_(*this); }
  std::function<void(LtBench&)> scenario_;
};

TEST(TargetReports, ARefusedIgnoreCommandIsReportedAsIgnore) {
  const std::vector<std::string>& reports = capture_refusal_reports();
  constexpr std::uint64_t hole = map_size;  // the first offset beyond the map
  tlm::tlm_response_status response = tlm::TLM_OK_RESPONSE;
  LtBench bench("bench", [&](LtBench& b) {
    std::uint32_t word = 0;
    response = transport(b.socket, tlm::TLM_IGNORE_COMMAND, hole, &word, 4);
  });
  sc_core::sc_start();
  EXPECT_EQ(response, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_NE(reports[0].find("ignore of 4 byte(s) at offset 0x" + [] {
              char text[32];
              std::snprintf(text, sizeof text, "%llx", static_cast<unsigned long long>(map_size));
              return std::string(text);
            }()),
            std::string::npos)
      << reports[0];
  EXPECT_NE(reports[0].find("refused with TLM_ADDRESS_ERROR_RESPONSE"), std::string::npos) << reports[0];
  // Only the first refusal of each cause is reported (docs/tlm.md): the report says so.
  EXPECT_NE(reports[0].find("later refusals with this cause set STATUS only"), std::string::npos) << reports[0];
  // The first offset past the window is named as past it (docs/tlm.md: offsets
  // 0x0000-0x7FFF), not as a hole inside the map.
  EXPECT_NE(reports[0].find("decodes offsets below 0x8000"), std::string::npos) << reports[0];
}

// done_irq follows STATUS.done, 0 out of reset (docs/tlm.md's map): a platform line that
// starts high is driven low before any operation, not left high until the first one ends.
struct SilentInitiator : sc_core::sc_module {  // bound to the target, sends nothing
  tlm_utils::simple_initiator_socket<SilentInitiator> socket{"socket"};
  explicit SilentInitiator(sc_core::sc_module_name name) : sc_module(name) {}
};

TEST(TargetInterrupt, ALineThatStartsHighIsLowOutOfReset) {
  SpecularLtTarget target("target", Config{});
  SilentInitiator bus("bus");
  bus.socket.bind(target.socket);
  sc_core::sc_signal<bool> irq("irq", true);
  target.done_irq(irq);
  sc_core::sc_start(sc_core::sc_time(1, sc_core::SC_NS));
  EXPECT_FALSE(irq.read());
}

// A byte-enable array longer than the data: IEEE 1666 applies it byte for byte, so only
// its first data-length entries count (a mutant that also read the entry past the data
// survived every other test). Bytes 0-3 enabled, 4-7 disabled: the 4-byte write is whole.
TEST(TargetByteEnables, AnArrayLongerThanTheDataCountsOnlyAsFarAsTheData) {
  tlm::tlm_response_status response = tlm::TLM_INCOMPLETE_RESPONSE;
  std::uint32_t n_after = 0;
  LtBench bench("bench", [&](LtBench& b) {
    std::uint32_t n = 7;
    unsigned char enables[8] = {TLM_BYTE_ENABLED, TLM_BYTE_ENABLED, TLM_BYTE_ENABLED, TLM_BYTE_ENABLED,
                                TLM_BYTE_DISABLED, TLM_BYTE_DISABLED, TLM_BYTE_DISABLED, TLM_BYTE_DISABLED};
    response = transport(b.socket, tlm::TLM_WRITE_COMMAND, offset_of(Reg::n), &n, 4, enables, 8);
    transport(b.socket, tlm::TLM_READ_COMMAND, offset_of(Reg::n), &n_after, 4);
  });
  sc_core::sc_start();
  EXPECT_EQ(response, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(n_after, 7u);
}

// Three more the C++ mutants found untested (each seen killing its mutant):
// - a debug access with TLM_IGNORE_COMMAND moves no byte and returns 0 (docs/tlm.md);
// - a 1- or 2-byte read inside a window reads the word it falls in (BATCH_OUT + 4 is the
//   first operation's G, + 12 the second's R), the bytes of the host's word;
// - the report of a refused BATCH_COS word names that word's value, not another's.
TEST(TargetWindows, DebugIgnoreMovesNothingAndSubWordReadsFindTheirWord) {
  const std::vector<std::string>& reports = capture_refusal_reports();
  const Operands op{50000, 40, {200, 100, 50}};
  const Result first = Core().run(Operands{64000, op.n, op.rgb});
  const Result second = Core().run(Operands{65000, op.n, op.rgb});
  unsigned ignored = 99;
  std::uint8_t g_byte = 0;
  std::uint16_t r_half = 0;
  tlm::tlm_response_status batch_response = tlm::TLM_OK_RESPONSE;
  LtBench bench("bench", [&](LtBench& b) {
    const auto access = [&](tlm::tlm_command command, std::uint64_t address, void* data, unsigned length) {
      return transport(b.socket, command, address, data, length);
    };
    std::uint32_t word = 0;
    tlm::tlm_generic_payload dbg;
    dbg.set_command(tlm::TLM_IGNORE_COMMAND);
    dbg.set_address(offset_of(Reg::n));
    dbg.set_data_ptr(reinterpret_cast<unsigned char*>(&word));
    dbg.set_data_length(4);
    ignored = b.socket->transport_dbg(dbg);
    for (auto [reg, value] : {std::pair{Reg::n, op.n}, {Reg::r, op.rgb[0]}, {Reg::g, op.rgb[1]},
                              {Reg::b, op.rgb[2]}, {Reg::cos, op.cos}}) {
      word = static_cast<std::uint32_t>(value);
      access(tlm::TLM_WRITE_COMMAND, offset_of(reg), &word, 4);
    }
    word = control_bits::start;
    access(tlm::TLM_WRITE_COMMAND, offset_of(Reg::control), &word, 4);
    std::uint32_t pair[2] = {64000, 65000};  // cos 0.977 and 0.992: bright, R, G, B apart
    access(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), pair, 8);
    access(tlm::TLM_READ_COMMAND, offset_of(Reg::batch_out) + 4, &g_byte, 1);
    access(tlm::TLM_READ_COMMAND, offset_of(Reg::batch_out) + 12, &r_half, 2);
    std::uint32_t batch[3] = {1000, 2000, 70000};  // word 2 above 1.0 = 65536
    batch_response = access(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), batch, 12);
  });
  sc_core::sc_start();
  EXPECT_EQ(ignored, 0u) << "an ignore command moves no byte";
  // Pins 24-26 as 32-bit two's complement words in the host's byte order (docs/integration.md).
  const std::uint32_t g_word = static_cast<std::uint32_t>(first.out[1]);
  const std::uint32_t r_word = static_cast<std::uint32_t>(second.out[0]);
  std::uint8_t g_first = 0;
  std::uint16_t r_first = 0;
  std::memcpy(&g_first, &g_word, 1);
  std::memcpy(&r_first, &r_word, 2);
  ASSERT_NE(g_word & 0xFFu, static_cast<std::uint32_t>(first.out[0]) & 0xFFu) << "R and G must differ to tell the words apart";
  EXPECT_EQ(g_byte, g_first) << "byte 0 of the first operation's G";
  EXPECT_EQ(r_half, r_first) << "bytes 0-1 of the second operation's R";
  EXPECT_EQ(batch_response, tlm::TLM_GENERIC_ERROR_RESPONSE);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_NE(reports[0].find("BATCH_COS = 0x11170 (70000)"), std::string::npos) << reports[0];
}

// A batch that ends at BATCH_COS's last word (1022 and 1023): its results fill BATCH_OUT to
// its last word, and OUT_R..OUT_B hold the batch's last operation. Bit-identical to the
// core. Under the sanitizer job this also stops a read past BATCH_OUT's end.
TEST(TargetWindows, ABatchEndingAtTheWindowsLastWordFillsBatchOutToItsEnd) {
  const Operands op{0, 40, {200, 100, 50}};
  const std::uint32_t cos[2] = {64000, 65000};
  const Result first = Core().run(Operands{cos[0], op.n, op.rgb});
  const Result last = Core().run(Operands{cos[1], op.n, op.rgb});
  tlm::tlm_response_status response = tlm::TLM_INCOMPLETE_RESPONSE;
  std::uint32_t tail[6] = {};
  std::uint32_t out[3] = {};
  LtBench bench("bench", [&](LtBench& b) {
    for (auto [reg, value] : {std::pair{Reg::n, op.n}, {Reg::r, op.rgb[0]}, {Reg::g, op.rgb[1]},
                              {Reg::b, op.rgb[2]}}) {
      std::uint32_t word = static_cast<std::uint32_t>(value);
      transport(b.socket, tlm::TLM_WRITE_COMMAND, offset_of(reg), &word, 4);
    }
    std::uint32_t batch[2] = {cos[0], cos[1]};
    response = transport(b.socket, tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos) + 4 * (batch_capacity - 2),
                         batch, 8);
    transport(b.socket, tlm::TLM_READ_COMMAND, offset_of(Reg::batch_out) + 4 * 3 * (batch_capacity - 2), tail, 24);
    transport(b.socket, tlm::TLM_READ_COMMAND, offset_of(Reg::results), out, 12);
  });
  sc_core::sc_start();
  ASSERT_EQ(response, tlm::TLM_OK_RESPONSE);
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_EQ(tail[ch], static_cast<std::uint32_t>(first.out[ch])) << "operation 1022, channel " << ch;
    EXPECT_EQ(tail[3 + ch], static_cast<std::uint32_t>(last.out[ch])) << "operation 1023, channel " << ch;
    EXPECT_EQ(out[ch], static_cast<std::uint32_t>(last.out[ch])) << "RESULTS word " << ch;
  }
}

// Every word of a batch is checked before any runs, the first as much as the others: a
// batch whose word 0 is above 1.0 (65536 for U1.16) is refused whole, naming that word.
TEST(TargetWindows, ABatchWhoseFirstWordIsAboveOneIsRefusedWhole) {
  const std::vector<std::string>& reports = capture_refusal_reports();
  tlm::tlm_response_status response = tlm::TLM_OK_RESPONSE;
  std::uint32_t error_address = 0;
  LtBench bench("bench", [&](LtBench& b) {
    std::uint32_t batch[2] = {70000, 1000};
    response = transport(b.socket, tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), batch, 8);
    transport(b.socket, tlm::TLM_READ_COMMAND, offset_of(Reg::error_address), &error_address, 4);
  });
  sc_core::sc_start();
  EXPECT_EQ(response, tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(error_address, offset_of(Reg::batch_cos));
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_NE(reports[0].find("BATCH_COS = 0x11170 (70000)"), std::string::npos) << reports[0];
}

// The report of a refused OPERANDS burst names the refused word's own value, not another
// word's: N = 2000 (word 1 of COS, N, R, G, B, CONTROL) is outside 1..1000.
TEST(TargetWindows, ARefusedOperandsWordIsReportedWithItsOwnValue) {
  const std::vector<std::string>& reports = capture_refusal_reports();
  tlm::tlm_response_status response = tlm::TLM_OK_RESPONSE;
  LtBench bench("bench", [&](LtBench& b) {
    std::uint32_t operands[6] = {1000, 2000, 1, 2, 3, 0};
    response = transport(b.socket, tlm::TLM_WRITE_COMMAND, offset_of(Reg::operands), operands, 24);
  });
  sc_core::sc_start();
  EXPECT_EQ(response, tlm::TLM_GENERIC_ERROR_RESPONSE);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_NE(reports[0].find("N = 0x7d0 (2000)"), std::string::npos) << reports[0];
}

// A byte written to STATUS replaces that byte and W1C sees zeros elsewhere (docs/tlm.md):
// writing 0 to the cause byte (byte 1) after an operation leaves done (bit 1 of byte 0) set.
TEST(TargetSubWord, AByteWrittenToStatusClearsNothingInItsOtherBytes) {
  std::uint32_t before = 0, after = 0;
  LtBench bench("bench", [&](LtBench& b) {
    for (auto [reg, value] : {std::pair{Reg::n, 40u}, {Reg::r, 200u}, {Reg::g, 100u}, {Reg::b, 50u},
                              {Reg::cos, 60000u}}) {
      std::uint32_t word = value;
      transport(b.socket, tlm::TLM_WRITE_COMMAND, offset_of(reg), &word, 4);
    }
    std::uint32_t word = control_bits::start;
    transport(b.socket, tlm::TLM_WRITE_COMMAND, offset_of(Reg::control), &word, 4);
    transport(b.socket, tlm::TLM_READ_COMMAND, offset_of(Reg::status), &before, 4);
    std::uint8_t zero = 0;
    transport(b.socket, tlm::TLM_WRITE_COMMAND, offset_of(Reg::status) + 1, &zero, 1);
    transport(b.socket, tlm::TLM_READ_COMMAND, offset_of(Reg::status), &after, 4);
  });
  sc_core::sc_start();
  ASSERT_NE(before & status_bits::done, 0u) << "the operation must have ended";
  EXPECT_NE(after & status_bits::done, 0u) << "STATUS.done cleared by a write to byte 1";
}

}  // namespace
}  // namespace specular
