// The TLM target's register file (docs/tlm.md): identification, reset values,
// read-only CONFIG, operand registers, STATUS/CONTROL semantics, the bus checks with
// their TLM responses and STATUS causes, and the debug transport. Expected values are
// the documented constants, computed here by hand.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "register_docs.h"
#include "support/tlm_bench.h"

namespace specular {
namespace {

using namespace tlm_testing;

constexpr std::uint32_t cause_of(ErrorCause cause) { return static_cast<std::uint32_t>(cause); }

/// The last access was refused with `cause` at `address`; clears the error (W1C).
void expect_refused(Endpoint& e, ErrorCause cause, std::uint32_t address, const char* what) {
  const std::uint32_t status = e.read(Reg::status);
  EXPECT_TRUE(status & status_bits::error) << what;
  EXPECT_EQ((status & status_bits::cause_mask) >> status_bits::cause_shift, cause_of(cause))
      << what << ": expected cause " << to_string(cause);
  EXPECT_EQ(e.read(Reg::error_address), address) << what;
  EXPECT_EQ(e.write(Reg::status, status_bits::error), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(e.read(Reg::status) & (status_bits::error | status_bits::cause_mask), 0u) << what;
}

TEST(TlmRegisters, IdentificationAndResetValues) {
  run({Kind::lt}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    EXPECT_EQ(e.read(Reg::id), 0x00059965u) << "UA 59965 U";
    EXPECT_EQ(e.read(Reg::version), 0x00010001u) << "map version 1.1";
    // Default device: patent (0), clamp (0), COS U1.16, OUT S18.13, RGB 8 bits.
    EXPECT_EQ(e.read(Reg::config), (8u << 24) | (13u << 16) | (16u << 8));
    EXPECT_EQ(e.read(Reg::status), 0u) << "idle, nothing done, no error";
    EXPECT_EQ(e.read(Reg::control), 0u);
    EXPECT_EQ(e.read(Reg::batch_capacity), 1024u);
    EXPECT_EQ(e.read(Reg::error_address), 0u);
    EXPECT_EQ(e.read(Reg::pin19_h), 0x80u) << "½ on U10.8";
    EXPECT_EQ(e.read(Reg::pin20_a), 0x400000u) << "1.0 on S14.22";
    EXPECT_EQ(e.read(Reg::cos), 0u);
    EXPECT_EQ(e.read(Reg::n), 1u) << "n resets to the smallest legal value";
    for (Reg reg : {Reg::r, Reg::g, Reg::b, Reg::out_r, Reg::out_g, Reg::out_b, Reg::reg1,
                    Reg::reg9_pass1_lo, Reg::reg9_pass1_hi, Reg::reg9_pass2_lo,
                    Reg::reg9_pass2_hi, Reg::rom38_k, Reg::norm39})
      EXPECT_EQ(e.read(reg), 0u) << info(reg).name;
    EXPECT_FALSE(e.irq.read()) << "done_irq low after construction";
  });
}

TEST(TlmRegisters, ConfigShowsThePoliciesAndIsReadOnly) {
  Config config;
  config.normalisation = Normalisation::none;
  config.saturation = Saturation::literal;
  run(
      {Kind::lt},
      [](TlmBench& b) {
        Endpoint& e = b.at(0);
        const std::uint32_t expected = (8u << 24) | (13u << 16) | (16u << 8) | (1u << 4) | 2u;
        EXPECT_EQ(e.read(Reg::config), expected);
        std::uint32_t value = 0;  // try to switch to patent/clamp
        EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::config), &value, 4),
                  tlm::TLM_COMMAND_ERROR_RESPONSE);
        expect_refused(e, ErrorCause::read_only, offset_of(Reg::config), "CONFIG write");
        EXPECT_EQ(e.read(Reg::config), expected) << "unchanged";
        // Every read-only register and window refuses writes the same way.
        for (Reg reg : {Reg::id, Reg::version, Reg::batch_capacity, Reg::error_address,
                        Reg::out_r, Reg::out_b, Reg::reg1, Reg::rom38_k, Reg::norm39,
                        Reg::batch_out}) {
          EXPECT_EQ(e.write(reg, 5), tlm::TLM_COMMAND_ERROR_RESPONSE) << info(reg).name;
          expect_refused(e, ErrorCause::read_only, offset_of(reg), info(reg).name);
        }
        EXPECT_EQ(e.read(Reg::id), 0x00059965u);
      },
      config);
}

TEST(TlmRegisters, ConstantsAreFixedAtConstructionAndReadable) {
  Config config;
  config.constants = Constants::minimax;
  config.normalisation = Normalisation::device_energy;
  run(
      {Kind::lt, Kind::pin},
      [](TlmBench& b) {
        for (std::size_t i = 0; i < 2; ++i) {
          Endpoint& e = b.at(i);
          // CONFIG[6:5] = 2 (minimax), [1:0] = 3 (device-energy).
          EXPECT_EQ(e.read(Reg::config), (8u << 24) | (13u << 16) | (16u << 8) | (2u << 5) | 3u);
          EXPECT_EQ(e.read(Reg::pin19_h), 41u) << "h = 41/256 on U10.8";
          EXPECT_EQ(e.read(Reg::pin20_a), 1564586u) << "a = 0.373026371 on S14.22";
          EXPECT_EQ(e.write(Reg::pin19_h, 128), tlm::TLM_COMMAND_ERROR_RESPONSE);
          expect_refused(e, ErrorCause::read_only, offset_of(Reg::pin19_h), "PIN19_H write");
          EXPECT_EQ(e.write(Reg::pin20_a, 1), tlm::TLM_COMMAND_ERROR_RESPONSE);
          expect_refused(e, ErrorCause::read_only, offset_of(Reg::pin20_a), "PIN20_A write");
          EXPECT_EQ(e.read(Reg::pin19_h), 41u) << "unchanged";
        }
      },
      config);
}

TEST(TlmRegisters, OperandRegistersHoldWhatIsWrittenAcrossTheirRange) {
  run({Kind::lt}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    const std::vector<std::pair<Reg, std::vector<std::uint32_t>>> cases = {
        {Reg::cos, {0, 1, 32768, 65535, 65536}},
        {Reg::n, {1, 2, 500, 999, 1000}},
        {Reg::r, {0, 1, 128, 255}},
        {Reg::g, {0, 77, 255}},
        {Reg::b, {255, 0, 3}}};
    for (const auto& [reg, values] : cases)
      for (const std::uint32_t v : values) {
        EXPECT_EQ(e.write(reg, v), tlm::TLM_OK_RESPONSE) << info(reg).name << " = " << v;
        EXPECT_EQ(e.read(reg), v) << info(reg).name;
      }
    EXPECT_EQ(e.read(Reg::status), 0u) << "no refusal, no operation";
  });
}

// Out of range values: TLM_GENERIC_ERROR_RESPONSE and a cause, never a clamp — the
// register keeps its previous value.
TEST(TlmRegisters, OutOfRangeValuesAreRefusedNotClamped) {
  run({Kind::lt}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    ASSERT_EQ(e.write(Reg::n, 17), tlm::TLM_OK_RESPONSE);
    ASSERT_EQ(e.write(Reg::cos, 40000), tlm::TLM_OK_RESPONSE);
    ASSERT_EQ(e.write(Reg::g, 9), tlm::TLM_OK_RESPONSE);
    struct Case {
      Reg reg;
      std::uint32_t value;
      ErrorCause cause;
      std::uint32_t kept;
    };
    for (const Case& c : {Case{Reg::n, 0, ErrorCause::n_out_of_range, 17},
                          Case{Reg::n, 1001, ErrorCause::n_out_of_range, 17},
                          Case{Reg::n, 0xFFFFFFFF, ErrorCause::n_out_of_range, 17},
                          Case{Reg::cos, 65537, ErrorCause::cos_out_of_range, 40000},
                          Case{Reg::cos, 0x80000000, ErrorCause::cos_out_of_range, 40000},
                          Case{Reg::g, 256, ErrorCause::rgb_out_of_range, 9},
                          Case{Reg::r, 1000, ErrorCause::rgb_out_of_range, 0}}) {
      EXPECT_EQ(e.write(c.reg, c.value), tlm::TLM_GENERIC_ERROR_RESPONSE)
          << info(c.reg).name << " = " << c.value;
      expect_refused(e, c.cause, offset_of(c.reg), info(c.reg).name);
      EXPECT_EQ(e.read(c.reg), c.kept) << info(c.reg).name << ": not clamped, not changed";
    }
    // A batch with one bad cos word computes nothing: all or nothing.
    std::uint32_t batch[3] = {0, 65536, 65537};
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), batch, 12),
              tlm::TLM_GENERIC_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::cos_out_of_range, offset_of(Reg::batch_cos) + 8, "BATCH_COS");
    EXPECT_EQ(e.read(Reg::status) & status_bits::done, 0u) << "nothing ran";
    EXPECT_FALSE(e.irq.read());
  });
}

// The bus checks in Accellera's order, each with its response and cause.
TEST(TlmRegisters, BusErrorsGetTheirTlmResponses) {
  run({Kind::lt}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    std::uint32_t words[4] = {1, 2, 3, 4};
    // Address: a hole in the map, a misaligned offset, beyond the map.
    for (const std::uint32_t address : {0x01Cu, 0x026u, 0x8000u}) {
      EXPECT_EQ(e.transport(tlm::TLM_READ_COMMAND, address, words, 4),
                tlm::TLM_ADDRESS_ERROR_RESPONSE);
      expect_refused(e, ErrorCause::address, address, "address");
    }
    // Burst: 8 bytes on a register off a doubleword offset, 3 bytes, a sub-word write to
    // a window, streaming on a window (docs/integration.md: the access widths).
    EXPECT_EQ(e.transport(tlm::TLM_READ_COMMAND, offset_of(Reg::n), words, 8),
              tlm::TLM_BURST_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::burst, offset_of(Reg::n), "8-byte read of N at 0x24");
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::n), words, 3),
              tlm::TLM_BURST_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::burst, offset_of(Reg::n), "3-byte write of N");
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), words, 2),
              tlm::TLM_BURST_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::burst, offset_of(Reg::batch_cos), "2-byte write of BATCH_COS");
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), words, 16, 4),
              tlm::TLM_BURST_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::burst, offset_of(Reg::batch_cos), "streaming width 4");
    // Byte enables: one byte disabled.
    unsigned char enables[4] = {TLM_BYTE_ENABLED, TLM_BYTE_DISABLED, TLM_BYTE_ENABLED,
                                TLM_BYTE_ENABLED};
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::n), words, 4, 0, enables, 4),
              tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::byte_enable, offset_of(Reg::n), "byte enables");
    // ... while all-enabled byte enables are fine.
    enables[1] = TLM_BYTE_ENABLED;
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::n), words, 4, 0, enables, 4),
              tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(e.read(Reg::n), 1u);
    // Command: CONTROL with an undefined bit, then a write to read-only ID.
    EXPECT_EQ(e.write(Reg::control, 0x2), tlm::TLM_GENERIC_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::reserved_bits, offset_of(Reg::control), "CONTROL bit 1");
    EXPECT_EQ(e.write(Reg::id, 0), tlm::TLM_COMMAND_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::read_only, offset_of(Reg::id), "ID");
    // TLM_IGNORE_COMMAND is accepted and does nothing.
    EXPECT_EQ(e.transport(tlm::TLM_IGNORE_COMMAND, offset_of(Reg::control), words, 4),
              tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(e.read(Reg::status), 0u);
  });
}

// STATUS.done is set by an operation, drives done_irq, and clears on writing 1;
// CONTROL reads 0 (START is self-clearing); a later error does not disturb done.
// Register 9's high words (a C++ mutant that left REG9_PASS1_HI unwritten survived: every
// other test's pass 1 stays below 1024, so its high word is the reset value 0). cos code 1
// is 2^-16, whose log2 ROM 5 gives exactly: pass 1 = a − n·log2 cos = 1 + 100·16 = 1601,
// on S14.22 the code 1601·2^22 = 0x1'9040'0000. Pass 2 = 1 − ½·log2 1601 ≈ −4.3: under
// `literal` negative, so its high word is all ones.
TEST(TlmRegisters, InspectionRegistersHoldRegister9sHighWords) {
  Config config;
  config.saturation = Saturation::literal;
  run(
      {Kind::lt},
      [](TlmBench& b) {
        Endpoint& e = b.at(0);
        ASSERT_EQ(e.write(Reg::n, 100), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(e.write(Reg::cos, 1), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(e.write(Reg::control, control_bits::start), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(e.read(Reg::reg9_pass1_hi), 0x1u);
        EXPECT_EQ(e.read(Reg::reg9_pass1_lo), 0x90400000u);
        EXPECT_EQ(e.read(Reg::reg9_pass2_hi), 0xFFFFFFFFu) << "pass 2 is negative under literal";
      },
      config);
}

TEST(TlmRegisters, StatusDoneIsWriteOneToClearAndControlReadsZero) {
  run({Kind::lt}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    ASSERT_EQ(e.write(Reg::cos, 65536), tlm::TLM_OK_RESPONSE);
    ASSERT_EQ(e.write(Reg::control, control_bits::start), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(e.read(Reg::control), 0u);
    EXPECT_EQ(e.read(Reg::status), status_bits::done);
    EXPECT_TRUE(e.irq.read());
    EXPECT_EQ(e.write(Reg::status, status_bits::busy), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(e.read(Reg::status), status_bits::done) << "writing busy or 0 changes nothing";
    EXPECT_EQ(e.write(Reg::n, 0), tlm::TLM_GENERIC_ERROR_RESPONSE);
    EXPECT_EQ(e.read(Reg::status),
              status_bits::done | status_bits::error | (cause_of(ErrorCause::n_out_of_range) << 8));
    EXPECT_EQ(e.write(Reg::status, status_bits::done), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(e.read(Reg::status), status_bits::error | (cause_of(ErrorCause::n_out_of_range) << 8))
        << "done cleared, error kept";
    wait(sc_core::SC_ZERO_TIME);  // done_irq follows at the write's time
    EXPECT_FALSE(e.irq.read());
  });
}

// transport_dbg: reads and writes without time, side effects or STATUS changes.
TEST(TlmRegisters, DebugTransportReadsAndWrites) {
  run({Kind::lt}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    std::uint32_t three[3] = {};
    EXPECT_EQ(e.debug(tlm::TLM_READ_COMMAND, offset_of(Reg::id), three, 12), 12u);
    EXPECT_EQ(three[0], 0x00059965u);
    EXPECT_EQ(three[1], 0x00010001u);
    EXPECT_EQ(three[2], (8u << 24) | (13u << 16) | (16u << 8));

    std::uint32_t n = 640;
    EXPECT_EQ(e.debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::n), &n, 4), 4u);
    EXPECT_EQ(e.read(Reg::n), 640u);
    std::uint32_t bad = 1001;  // refused: debug writes keep the range check
    EXPECT_EQ(e.debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::n), &bad, 4), 0u);
    EXPECT_EQ(e.read(Reg::n), 640u);
    std::uint32_t id = 0;  // read-only: not written
    EXPECT_EQ(e.debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::id), &id, 4), 0u);
    std::uint32_t start = control_bits::start;  // CONTROL is not storage: no operation
    EXPECT_EQ(e.debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::control), &start, 4), 0u);
    EXPECT_EQ(e.read(Reg::status), 0u) << "no done, no error from debug accesses";

    // BATCH_COS words written by debug read back, and compute nothing.
    std::uint32_t cos[2] = {65536, 12345};
    EXPECT_EQ(e.debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos) + 40, cos, 8), 8u);
    std::uint32_t back[2] = {};
    EXPECT_EQ(e.debug(tlm::TLM_READ_COMMAND, offset_of(Reg::batch_cos) + 40, back, 8), 8u);
    EXPECT_EQ(back[0], 65536u);
    EXPECT_EQ(back[1], 12345u);
    // A debug read running into a hole stops there: ERROR_ADDRESS (0x18), hole (0x1C).
    std::uint32_t two[2] = {};
    EXPECT_EQ(e.debug(tlm::TLM_READ_COMMAND, offset_of(Reg::error_address), two, 8), 4u);
    EXPECT_EQ(e.debug(tlm::TLM_READ_COMMAND, 0x2, two, 4), 0u) << "misaligned";
    EXPECT_EQ(sc_core::sc_time_stamp(), sc_core::SC_ZERO_TIME) << "no time passed";
    EXPECT_EQ(e.read(Reg::status), 0u);
  });
}

// The pin transactor holds its operands while an operation runs: a second master's
// operand writes and START wait their turn (issue 20) instead of being refused, so the
// running result is intact and the queued writes then land in arrival order.
TEST(TlmRegisters, PinTargetQueuesOperandWritesWhileBusy) {
  std::uint32_t busy_status = 0, status_after = 0;
  std::vector<tlm::tlm_response_status> queued;
  std::vector<sc_time> returned;
  std::uint32_t out_r = 0, n_final = 0, cos_final = 0;
  run(
      {Kind::pin},
      [&](TlmBench& b) {
        Endpoint& e = b.at(0);
        ASSERT_EQ(e.write(Reg::cos, 65536), tlm::TLM_OK_RESPONSE);  // cos 1: A = 1
        ASSERT_EQ(e.write(Reg::n, 2), tlm::TLM_OK_RESPONSE);        // K = 2π/4
        ASSERT_EQ(e.write(Reg::r, 100), tlm::TLM_OK_RESPONSE);
        b.until(sc_time(40, SC_NS));
        ASSERT_EQ(e.write(Reg::control, control_bits::start), tlm::TLM_OK_RESPONSE);
        out_r = e.read(Reg::out_r);  // reads never wait: served before the queued writes
      },
      Config{}, sc_time(10, SC_NS),
      [&](TlmBench& b) {
        Endpoint& e = b.at(0);
        b.until(sc_time(55, SC_NS));  // busy from 40 ns: reset 40–50, start at 60, done 85
        busy_status = e.read(Reg::status);
        queued.push_back(e.write(Reg::n, 3));
        returned.push_back(sc_core::sc_time_stamp());
        queued.push_back(e.write(Reg::cos, 0));
        returned.push_back(sc_core::sc_time_stamp());
        status_after = e.read(Reg::status);
        n_final = e.read(Reg::n);
        cos_final = e.read(Reg::cos);
      });
  EXPECT_TRUE(busy_status & status_bits::busy);
  ASSERT_EQ(queued.size(), 2u);
  for (const auto r : queued) EXPECT_EQ(r, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(returned[0], sc_time(85, SC_NS)) << "N waits until pin 35 rises";
  EXPECT_EQ(returned[1], sc_time(85, SC_NS)) << "COS is served at once after it";
  EXPECT_FALSE(status_after & status_bits::error);
  EXPECT_EQ(n_final, 3u);
  EXPECT_EQ(cos_final, 0u);
  // K·A·R = (2π/4)·1·100 = 157.08 in S18.13, within one output LSB plus 2^-10·K·R.
  EXPECT_NEAR(static_cast<std::int32_t>(out_r) / 8192.0, 2 * M_PI / 4 * 100,
              std::ldexp(1.0, -10) * 1.571 * 100 + 1.0 / 8192);
}

std::string read_source(const std::string& relative) {
  std::ifstream in(std::string(SPECULAR_SOURCE_DIR) + "/" + relative, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// docs/tlm/registers.md and docs/misuse.md carry the tables the register map prints,
// exactly, between their markers (specular_register_docs --write rewrites them).
TEST(TlmRegisters, DocsCarryTheRegisterTablesExactly) {
  for (const register_docs::GeneratedTable& t : register_docs::generated_tables()) {
    const std::string doc = read_source(t.file);
    ASSERT_FALSE(doc.empty()) << t.file;
    const auto table = register_docs::region(doc, t.name);
    ASSERT_TRUE(table) << t.file << " lacks the markers of '" << t.name << "'";
    EXPECT_EQ(*table, register_docs::region_text(t))
        << t.file << ": table '" << t.name << "' differs from the register map; run "
        << "specular_register_docs --write <source dir>";
  }
}

// The comparison above can fail: one changed cell, or a marker lost, is caught.
TEST(TlmRegisters, ADocThatDriftsFromTheMapIsCaught) {
  const register_docs::GeneratedTable t = register_docs::generated_tables().front();
  const std::string doc = read_source(t.file);
  std::string drifted = register_docs::region_text(t);
  const std::size_t at = drifted.find("| PIN19_H |");
  ASSERT_NE(at, std::string::npos);
  drifted.replace(at, 11, "| PIN19_X |");
  const auto edited = register_docs::with_region(doc, t.name, drifted);
  ASSERT_TRUE(edited);
  EXPECT_NE(*register_docs::region(*edited, t.name), register_docs::region_text(t));
  std::string unmarked = doc;
  unmarked.erase(unmarked.find(register_docs::end_marker(t.name)), 1);
  EXPECT_FALSE(register_docs::region(unmarked, t.name)) << "a damaged end marker";
}

// The facts the hand-written tables got wrong, and the holes, written out here from
// docs/tlm.md's offsets: 0x06C is PIN19_H; OPERANDS word 1 (N) reads 1 after reset.
TEST(TlmRegisters, AddressMapListsEveryHoleAndTheAliasedResets) {
  const std::string map = address_map_markdown();
  EXPECT_NE(map.find("| 0x06C | PIN19_H | RO | 0x00000080 |"), std::string::npos) << map;
  const std::string operands = "| 0x080–0x097 | OPERANDS | RW | 0x00000000; word 1 (N): 0x00000001 |";
  EXPECT_NE(map.find(operands), std::string::npos) << map;
  EXPECT_NE(register_map_markdown().find(operands), std::string::npos);
  std::vector<std::string> holes;
  std::istringstream lines(map);
  for (std::string line; std::getline(lines, line);)
    if (line.find("| *hole* |") != std::string::npos) holes.push_back(line.substr(2, line.find(" |") - 2));
  EXPECT_EQ(holes, (std::vector<std::string>{"0x01C–0x01F", "0x034–0x03F", "0x04C–0x04F", "0x074–0x07F",
                                              "0x098–0x09F", "0x0AC–0xFFF", "0x2000–0x3FFF",
                                              "0x7000–0x7FFF"}));
  EXPECT_NE(map.find("| ≥ 0x8000 | outside the map |"), std::string::npos);
}

// Every word of every register and window reads, after construction, what the map's
// reset (reset_of_word) says, on both implementations; OPERANDS word 1 reads N = 1.
TEST(TlmRegisters, EveryWordReadsItsMappedResetValue) {
  run({Kind::lt, Kind::pin}, [](TlmBench& b) {
    for (std::size_t k = 0; k < 2; ++k) {
      Endpoint& e = b.at(k);
      for (const RegisterInfo& row : register_map) {
        const std::uint32_t words = row.words < 8 ? row.words : 8;
        std::vector<std::uint32_t> data(words, 0xDEADBEEF);
        ASSERT_EQ(e.debug(tlm::TLM_READ_COMMAND, row.offset, data.data(), 4 * words), 4 * words)
            << row.name;
        for (std::uint32_t w = 0; w < words; ++w)
          EXPECT_EQ(data[w], reset_of_word(row, w)) << row.name << " word " << w;
      }
      std::uint32_t operands[6] = {};
      ASSERT_EQ(e.transport(tlm::TLM_READ_COMMAND, offset_of(Reg::operands), operands, 24),
                tlm::TLM_OK_RESPONSE);
      EXPECT_EQ(operands[1], 1u) << "OPERANDS word 1 is N, which resets to 1";
    }
  });
}

// docs/tlm.md carries the consumer example verbatim.
TEST(TlmRegisters, DocsCarryTheConsumerExample) {
  const std::string doc = read_source("docs/tlm.md");
  std::stringstream s(doc);
  // The ten-line example is examples/consumer/main.cpp's [example] region, verbatim.
  std::ifstream consumer(std::string(SPECULAR_SOURCE_DIR) + "/examples/consumer/main.cpp");
  ASSERT_TRUE(consumer) << "examples/consumer/main.cpp";
  std::string line, example;
  int markers = 0;
  while (std::getline(consumer, line)) {
    if (line.find("// [example]") != std::string::npos) {
      ++markers;
      continue;
    }
    if (markers == 1) example += line + "\n";
  }
  ASSERT_EQ(markers, 2);
  EXPECT_NE(s.str().find("```cpp\n" + example + "```"), std::string::npos)
      << "docs/tlm.md should carry the example:\n" << example;
}

// The example itself, as built by the project: it checks its own result against the
// double reference and exits 0.
TEST(TlmRegisters, ConsumerExampleRunsAndPasses) {
  const std::string exe = std::string(SPECULAR_BINARY_DIR) + "/examples/specular_consumer_example";
  ASSERT_EQ(std::system(("'" + exe + "' >/dev/null 2>&1").c_str()), 0) << exe;
}

}  // namespace
}  // namespace specular
