// The OPERANDS and RESULTS blocks of the register map (docs/tlm.md): COS, N, R, G, B
// and CONTROL written in one burst, OUT_R, OUT_G, OUT_B read in one burst
// (SpecularDriver::compute_burst). Results are checked against the double reference
// and, on both implementations, against Core::run; offsets, causes and ERROR_ADDRESS
// values are the documented constants, written out by hand.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "specular/reference.h"
#include "support/tlm_bench.h"

namespace specular {
namespace {

using namespace tlm_testing;

// The documented layout, by hand (docs/tlm.md).
constexpr std::uint32_t operands_at = 0x080;  // COS, N, R, G, B, CONTROL
constexpr std::uint32_t results_at = 0x0A0;   // OUT_R, OUT_G, OUT_B
constexpr std::uint32_t start = 1;

constexpr std::uint32_t cause_of(ErrorCause cause) { return static_cast<std::uint32_t>(cause); }

/// The last access was refused with `cause` at `address`; clears the error (W1C).
void expect_refused(Endpoint& e, ErrorCause cause, std::uint32_t address, const char* what) {
  const std::uint32_t status = e.read(Reg::status);
  EXPECT_TRUE(status & status_bits::error) << what;
  EXPECT_EQ((status & status_bits::cause_mask) >> status_bits::cause_shift, cause_of(cause))
      << what << ": expected cause " << to_string(cause);
  EXPECT_EQ(e.read(Reg::error_address), address) << what;
  EXPECT_EQ(e.write(Reg::status, status_bits::error), tlm::TLM_OK_RESPONSE);
}

/// A refusal of the payload's shape (streaming, a partial word): on axi the transactor
/// refuses it before the bus, as AXI4-Lite cannot carry it, and the RTL's STATUS stays
/// clear (docs/rtl_ip.md); elsewhere as expect_refused.
void expect_shape_refused(Endpoint& e, ErrorCause cause, std::uint32_t address, const char* what) {
  if (e.kind == Kind::axi)
    EXPECT_FALSE(e.read(Reg::status) & status_bits::error) << what << ": refused before the bus";
  else
    expect_refused(e, cause, address, what);
}

/// COS, N, R, G, B as the single registers hold them.
std::array<std::uint32_t, 5> single_registers(Endpoint& e) {
  return {e.read(Reg::cos), e.read(Reg::n), e.read(Reg::r), e.read(Reg::g), e.read(Reg::b)};
}

void expect_near_reference(const Operands& in, const std::array<std::int32_t, 3>& out) {
  const Config config;
  const Formats f(config.widths);
  const std::array<double, 3> intensity{double(in.rgb[0]), double(in.rgb[1]), double(in.rgb[2])};
  const reference::Figures ref =
      reference::evaluate(f.cos.to_real(in.cos), static_cast<unsigned>(in.n), intensity,
                          config.normalisation, config.saturation, config.widths.cos_frac_bits);
  const double k = reference::k(static_cast<unsigned>(in.n), config.normalisation);
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(f.out.to_real(out[ch]), ref.out_ref[ch],
                reference::out_tolerance(k, intensity[ch], f.out.lsb()))
        << "cos " << in.cos << ", n " << in.n << ", channel " << ch;
}

class OperandBurst : public ::testing::TestWithParam<Kind> {};

// Random operations whose n and R, G, B change every time, two bursts each: the bits
// of Core::run on the same operands, within the reference's tolerance.
TEST_P(OperandBurst, ComputeBurstGivesTheCoresBitsAndMeetsTheReference) {
  const Kind kind = GetParam();
  const int operations = kind == Kind::lt ? 2000 : 60;
  run({kind}, [&](TlmBench& b) {
    Endpoint& e = b.at(0);
    const Core core{Config{}};
    std::mt19937 random(59965);
    std::uniform_int_distribution<std::uint32_t> cos(0, 65536), n(1, 1000), rgb(0, 255);
    for (int i = 0; i < operations; ++i) {
      Operands in;
      in.cos = i == 0 ? 65536 : (i == 1 ? 0 : cos(random));  // both ends of cos λ
      in.n = i == 2 ? 1000 : n(random);
      in.rgb = {rgb(random), rgb(random), rgb(random)};
      const std::array<std::int32_t, 3> out = e.driver.compute_burst(in);
      const Result expected = core.run(in);
      for (int ch = 0; ch < 3; ++ch)
        ASSERT_EQ(out[ch], expected.out[ch]) << "operation " << i << ", channel " << ch;
      expect_near_reference(in, out);
      if (::testing::Test::HasFailure()) return;
    }
    e.driver.compute_burst({100, 7, {1, 2, 3}});
    EXPECT_EQ(single_registers(e), (std::array<std::uint32_t, 5>{100, 7, 1, 2, 3}))
        << "the registers hold the last burst's operands";
  });
}

// OPERANDS and RESULTS are the single registers under another address: what one
// writes, the other reads; a partial burst changes only the words it covers.
TEST_P(OperandBurst, TheBlocksAliasTheSingleRegisters) {
  run({GetParam()}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    std::uint32_t words[6] = {40000, 12, 200, 100, 50, 0};  // no START
    ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at, words, 20), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(single_registers(e), (std::array<std::uint32_t, 5>{40000, 12, 200, 100, 50}));
    EXPECT_FALSE(e.read(Reg::status) & status_bits::done) << "no START, no operation";

    ASSERT_EQ(e.write(Reg::n, 999), tlm::TLM_OK_RESPONSE);
    std::uint32_t back[6] = {1, 1, 1, 1, 1, 1};
    ASSERT_EQ(e.transport(tlm::TLM_READ_COMMAND, operands_at, back, 24), tlm::TLM_OK_RESPONSE);
    const std::uint32_t expected[6] = {40000, 999, 200, 100, 50, 0};  // CONTROL reads 0
    for (int i = 0; i < 6; ++i) EXPECT_EQ(back[i], expected[i]) << "OPERANDS word " << i;

    std::uint32_t green_blue[2] = {7, 8};  // words 3 and 4 only
    ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at + 12, green_blue, 8),
              tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(single_registers(e), (std::array<std::uint32_t, 5>{40000, 999, 200, 7, 8}));

    // START alone through word 5 runs on what the registers hold.
    std::uint32_t go = start;
    ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at + 20, &go, 4), tlm::TLM_OK_RESPONSE);
    EXPECT_TRUE(e.read(Reg::status) & status_bits::done);
    std::int32_t out[3] = {0, 0, 0};
    ASSERT_EQ(e.transport(tlm::TLM_READ_COMMAND, results_at, out, 12), tlm::TLM_OK_RESPONSE);
    const Result expected_out = Core{Config{}}.run({40000, 999, {200, 7, 8}});
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_EQ(out[ch], expected_out.out[ch]) << "RESULTS word " << ch;
      EXPECT_EQ(static_cast<std::int32_t>(e.read(static_cast<Reg>(index_of(Reg::out_r) + ch))),
                out[ch]);
    }
  });
}

// One bad word refuses the whole burst: nothing is stored, nothing runs, and
// ERROR_ADDRESS names the offending word.
TEST_P(OperandBurst, OneBadWordRefusesTheWholeBurst) {
  run({GetParam()}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    struct Case {
      int word;
      std::uint32_t value;
      ErrorCause cause;
    };
    const Case cases[] = {
        {0, 65537, ErrorCause::cos_out_of_range}, {1, 0, ErrorCause::n_out_of_range},
        {1, 1001, ErrorCause::n_out_of_range},    {2, 256, ErrorCause::rgb_out_of_range},
        {4, 256, ErrorCause::rgb_out_of_range},   {5, 3, ErrorCause::reserved_bits},
    };
    for (const Case& c : cases) {
      std::uint32_t words[6] = {30000, 20, 10, 11, 12, start};
      words[c.word] = c.value;
      EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at, words, 24),
                tlm::TLM_GENERIC_ERROR_RESPONSE)
          << "word " << c.word << " = " << c.value;
      expect_refused(e, c.cause, operands_at + 4 * c.word, to_string(c.cause));
      EXPECT_EQ(single_registers(e), (std::array<std::uint32_t, 5>{0, 1, 0, 0, 0}))
          << "reset values kept";
      EXPECT_FALSE(e.read(Reg::status) & status_bits::done) << "nothing ran";
    }
  });
}

// Bursts that run past a block, writes to RESULTS, streaming and partial words keep
// the bus errors every window has.
TEST_P(OperandBurst, BurstsPastTheBlocksAndBadShapesAreRefused) {
  run({GetParam()}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    std::uint32_t words[8] = {30000, 20, 10, 11, 12, start, 0, 0};
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at, words, 28),
              tlm::TLM_ADDRESS_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::address, 0x098, "7 words from OPERANDS");
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at + 16, words, 12),
              tlm::TLM_ADDRESS_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::address, 0x098, "3 words from OPERANDS word 4");
    EXPECT_EQ(e.transport(tlm::TLM_READ_COMMAND, results_at, words, 16),
              tlm::TLM_ADDRESS_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::address, 0x0AC, "4 words from RESULTS");
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, results_at, words, 12),
              tlm::TLM_COMMAND_ERROR_RESPONSE);
    expect_refused(e, ErrorCause::read_only, results_at, "write to RESULTS");
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at, words, 24, 4),
              tlm::TLM_BURST_ERROR_RESPONSE);
    expect_shape_refused(e, ErrorCause::burst, operands_at, "streaming width 4");
    EXPECT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at, words, 6),
              tlm::TLM_BURST_ERROR_RESPONSE);
    expect_shape_refused(e, ErrorCause::burst, operands_at, "6 bytes");
    EXPECT_EQ(single_registers(e), (std::array<std::uint32_t, 5>{0, 1, 0, 0, 0}))
        << "reset values kept";
    EXPECT_FALSE(e.read(Reg::status) & status_bits::done) << "nothing ran";
  });
}

INSTANTIATE_TEST_SUITE_P(BothImplementations, OperandBurst, ::testing::Values(Kind::lt, Kind::pin, Kind::axi),
                         [](const ::testing::TestParamInfo<Kind>& info) {
                           return std::string(to_string(info.param));
                         });

// While the pin model computes, a second master's burst into OPERANDS (with START)
// waits its turn instead of being refused (issue 20): the operation in flight finishes
// on its own operands, then the queued burst runs as the next operation. Reads never
// wait: the second master sees STATUS.busy meanwhile.
TEST(OperandBurstBusy, PinTargetQueuesABurstWhileAnOperationRuns) {
  tlm::tlm_response_status queued = tlm::TLM_INCOMPLETE_RESPONSE;
  std::uint32_t busy_status = 0, status_after = 0;
  sc_time queued_returned;
  std::int32_t out[3] = {0, 0, 0}, other_out[3] = {0, 0, 0};
  run(
      {Kind::pin},
      [&](TlmBench& b) {
        Endpoint& e = b.at(0);
        b.until(sc_time(40, SC_NS));
        std::uint32_t words[6] = {65536, 2, 100, 0, 0, start};  // cos 1, n 2: K·A·R = 2π/4·100
        ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at, words, 24), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(e.transport(tlm::TLM_READ_COMMAND, results_at, out, 12), tlm::TLM_OK_RESPONSE);
      },
      Config{}, sc_time(10, SC_NS),
      [&](TlmBench& b) {
        Endpoint& e = b.at(0);
        b.until(sc_time(55, SC_NS));  // busy from 40 ns: reset 40–50, start at 60, done 85
        busy_status = e.read(Reg::status);
        std::uint32_t other[6] = {65536, 2, 0, 100, 0, start};  // the same on G only
        queued = e.transport(tlm::TLM_WRITE_COMMAND, operands_at, other, 24);
        queued_returned = sc_core::sc_time_stamp();
        ASSERT_EQ(e.transport(tlm::TLM_READ_COMMAND, results_at, other_out, 12), tlm::TLM_OK_RESPONSE);
        status_after = e.read(Reg::status);
      });
  EXPECT_TRUE(busy_status & status_bits::busy);
  EXPECT_EQ(queued, tlm::TLM_OK_RESPONSE);
  EXPECT_FALSE(status_after & status_bits::error);
  // The first operation ends at 85 ns; the queued one starts at the next rising edge at
  // least a quarter period later (90 ns) and ends 2.5 periods after it.
  EXPECT_EQ(queued_returned, sc_time(115, SC_NS));
  const double tolerance = std::ldexp(1.0, -10) * 1.571 * 100 + 1.0 / 8192;
  EXPECT_NEAR(out[0] / 8192.0, 2 * M_PI / 4 * 100, tolerance);
  EXPECT_EQ(out[1], 0);
  EXPECT_EQ(out[2], 0);
  EXPECT_EQ(other_out[0], 0);
  EXPECT_NEAR(other_out[1] / 8192.0, 2 * M_PI / 4 * 100, tolerance);
  EXPECT_EQ(other_out[2], 0);
}

// A START inside the burst costs what START costs: 2.5 periods annotated on `lt`.
TEST(OperandBurstTiming, StartInTheBurstAnnotatesTheOperationsLatency) {
  run({Kind::lt}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    std::uint32_t words[6] = {50000, 30, 1, 2, 3, 0};
    sc_time annotated;
    ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at, words, 24, 0, nullptr, 0, &annotated),
              tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(annotated, sc_core::SC_ZERO_TIME) << "operands alone take no time";
    words[5] = start;
    ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, operands_at, words, 24, 0, nullptr, 0, &annotated),
              tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(annotated, sc_time(25, SC_NS)) << "2.5 periods of 10 ns";
  });
}

// The debug transport writes the operand storage through the block, checked, and
// stops at CONTROL: it never starts an operation.
TEST(OperandBurstDebug, DebugWritesStopAtControl) {
  run({Kind::lt}, [](TlmBench& b) {
    Endpoint& e = b.at(0);
    std::uint32_t words[6] = {1234, 56, 7, 8, 9, start};
    EXPECT_EQ(e.debug(tlm::TLM_WRITE_COMMAND, operands_at, words, 24), 20u);
    EXPECT_EQ(single_registers(e), (std::array<std::uint32_t, 5>{1234, 56, 7, 8, 9}));
    EXPECT_FALSE(e.read(Reg::status) & status_bits::done);
    std::uint32_t bad[2] = {100, 0};  // N = 0 is refused: one word done
    EXPECT_EQ(e.debug(tlm::TLM_WRITE_COMMAND, operands_at, bad, 8), 4u);
    EXPECT_EQ(e.read(Reg::cos), 100u);
    EXPECT_EQ(e.read(Reg::n), 56u);
  });
}

}  // namespace
}  // namespace specular
