// The C firmware driver (firmware/src/specular_driver.c, issue 35) as host-compiled
// firmware: the same C source, compiled as C99 and linked into this GoogleTest program,
// its bus accessors routed to a TLM target's socket from an SC_THREAD (a CPU with a
// quantum keeper, checked as riscv-vp's memory interface checks it: the returned delay
// never shrinks). On each of the four targets (lt, pin with PinDelay::keep, rtl,
// rtl-sync; one per test process):
//   - at least 10 000 operations, single ones (specular_compute) and batches
//     (specular_shade: one burst per chunk, and word by word), each polled and by
//     interrupt (done_irq's on_done_irq callback sets the driver's flag), every pin 24-26
//     and (single ones) register 9 equal to Core's — the bit-accurate core, computed here
//     independently of the target;
//   - accesses the IP refuses come back as SPECULAR_ERR_REFUSED with the ErrorCause.
// Without SystemC: each bad argument returns the code naming it and writes nothing.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "specular/specular_driver.h"
#include "specular/core.h"
#include "support/firmware_driver_cpu.h"
#include "support/firmware_targets.h"

namespace specular {
namespace {

using sc_core::sc_time;
using sc_core::SC_NS;

using firmware_driver::bind;
using firmware_driver::elaborate_and_run;
using firmware_driver::FirmwareCpu;
using firmware_driver::FirmwareTop;
using firmware_driver::ip_base;
using firmware_driver::period;
using firmware_driver::Tally;
using firmware_driver::TenThousandRun;
using firmware_targets::Kind;
using firmware_targets::kind_name;

class FirmwareDriver : public testing::TestWithParam<Kind> {};

TEST_P(FirmwareDriver, TenThousandOperationsEqualCorePolledAndByInterrupt) {
  TenThousandRun run;
  FirmwareTop& top =
      elaborate_and_run(GetParam(), [&](FirmwareCpu& cpu) { firmware_driver::ten_thousand_operations(cpu, run); });
  firmware_driver::expect_ten_thousand_passed(top, run);
  std::cout << "firmware driver: " << run.tally.operations << " operations equal to Core, "
            << top.cpu.irqs << " interrupts, " << sc_core::sc_time_stamp() << " simulated\n";
}

TEST_P(FirmwareDriver, RefusedAccessesComeBackAsErrorCodesWithTheirCause) {
  struct Case {
    std::uint32_t offset, value;
    ErrorCause cause;
  };
  const Case cases[] = {
      {offset_of(Reg::n), 0, ErrorCause::n_out_of_range},
      {offset_of(Reg::n), 1001, ErrorCause::n_out_of_range},
      {offset_of(Reg::cos), 65537, ErrorCause::cos_out_of_range},
      {offset_of(Reg::g), 256, ErrorCause::rgb_out_of_range},
      {offset_of(Reg::id), 1, ErrorCause::read_only},
      {offset_of(Reg::control), 2, ErrorCause::reserved_bits},
      {0x7FFC, 0, ErrorCause::address},
  };
  std::vector<std::string> failures;
  int wait_status = 0;
  std::uint32_t wait_cause = 0;
  FirmwareTop& top = elaborate_and_run(GetParam(), [&](FirmwareCpu& cpu) {
    bind(cpu, true, SPECULAR_WAIT_POLL);
    for (const Case& c : cases) {
      specular_write(&cpu.dev, c.offset, c.value);
      const int status = specular_check_error(&cpu.dev);
      if (status != SPECULAR_ERR_REFUSED || cpu.dev.cause != static_cast<std::uint32_t>(c.cause) ||
          cpu.dev.error_address != c.offset)
        failures.push_back(std::string(to_string(c.cause)) + ": status " + std::to_string(status) +
                           " cause " + std::to_string(cpu.dev.cause) + " at " +
                           std::to_string(cpu.dev.error_address));
      if (specular_check_error(&cpu.dev) != SPECULAR_OK) failures.push_back("not cleared");
    }
    // A refusal on the way to an operation: specular_wait reports it.
    specular_write(&cpu.dev, offset_of(Reg::cos), 70000);
    specular_write(&cpu.dev, offset_of(Reg::control), SPECULAR_CONTROL_START_MASK);
    wait_status = specular_wait(&cpu.dev);
    wait_cause = cpu.dev.cause;
    specular_ack(&cpu.dev);
  });
  EXPECT_TRUE(top.cpu.finished);
  EXPECT_TRUE(failures.empty()) << failures.front();
  EXPECT_EQ(wait_status, SPECULAR_ERR_REFUSED);
  EXPECT_EQ(wait_cause, static_cast<std::uint32_t>(ErrorCause::cos_out_of_range));
  EXPECT_EQ(top.cpu.refused, std::size(cases) + 1);
}

// Issue 47: every path a refusal can take through the driver, with poll_limit = 0 (no
// count: what a platform whose idle hook is wfi sets) — one operation and a batch (burst,
// and word by word), each polled and by interrupt. The driver is made to send a cos the
// IP refuses (its cos_max taken too wide, as from a misread CONFIG), so the refusal
// comes from the IP, not from the driver's own checks. Each path must return
// SPECULAR_ERR_REFUSED with the IP's cause and ERROR_ADDRESS, and the accessor records
// the fault as an ISS's trap would (mcause 7, mtval the address). A driver that stopped
// reporting the refusal would wait for ever: a refused BATCH_COS raises no interrupt, and
// sets no DONE; the CPU then parks (interrupt) or gives up after 10 000 polls, and the
// program does not finish. Afterwards a good operation succeeds (the error was cleared).
TEST_P(FirmwareDriver, EveryRefusalPathIsReportedWithNoPollLimit) {
  struct Path {
    const char* name;
    bool batch, bursts;
    specular_wait_mode mode;
  };
  const Path paths[] = {
      {"one operation, polled", false, true, SPECULAR_WAIT_POLL},
      {"one operation, by interrupt", false, true, SPECULAR_WAIT_IRQ},
      {"batch burst, polled", true, true, SPECULAR_WAIT_POLL},
      {"batch burst, by interrupt", true, true, SPECULAR_WAIT_IRQ},
      {"batch word by word, polled", true, false, SPECULAR_WAIT_POLL},
      {"batch word by word, by interrupt", true, false, SPECULAR_WAIT_IRQ},
  };
  const std::uint32_t refused_cos = 70000u;  // above 65536 (1.0 in U1.16)
  // axi: the RTL IP has no batch windows (BATCH_CAPACITY 0, docs/decisions.md), so
  // specular_shade runs pixel by pixel and the refusal is the COS write of pixel 1.
  const bool windows = !firmware_targets::is_axi(GetParam());
  std::vector<std::string> failures;
  std::size_t irqs_on_refused_burst = windows ? 1 : 0;
  FirmwareTop& top = elaborate_and_run(GetParam(), [&](FirmwareCpu& cpu) {
    for (const Path& path : paths) {
      bind(cpu, path.bursts, path.mode);
      cpu.dev.poll_limit = 0u;
      cpu.poll_idle_limit = 10000;
      cpu.poll_idles = 0;
      cpu.dev.cos_max = 0xFFFFFFFFu;
      const std::size_t faults_before = cpu.faults.size(), irqs_before = cpu.irqs;
      const std::uint32_t rgb[3] = {255u, 200u, 100u};
      int status;
      std::uint32_t expected_offset;
      if (path.batch) {
        const std::uint32_t cos[3] = {65536u, refused_cos, 1000u};
        std::int32_t out[9];
        status = specular_shade(&cpu.dev, 40u, rgb, cos, 3, out);
        expected_offset = windows ? SPECULAR_BATCH_COS_OFFSET + 4u : SPECULAR_COS_OFFSET;  // the refused word
        if (windows && path.bursts && path.mode == SPECULAR_WAIT_IRQ) irqs_on_refused_burst = cpu.irqs - irqs_before;
      } else {
        const specular_operands in{refused_cos, 40u, {255u, 200u, 100u}};
        specular_result result{};
        status = specular_compute(&cpu.dev, &in, &result);
        expected_offset = SPECULAR_COS_OFFSET;
      }
      const std::string name = path.name;
      if (status != SPECULAR_ERR_REFUSED)
        failures.push_back(name + ": returned " + specular_strerror(status));
      if (cpu.dev.cause != SPECULAR_STATUS_CAUSE_COS_OUT_OF_RANGE || cpu.dev.error_address != expected_offset)
        failures.push_back(name + ": cause " + std::to_string(cpu.dev.cause) + " at " +
                           std::to_string(cpu.dev.error_address));
      // The faulting store's address: the refused word's own, or a burst's first.
      const std::uint32_t fault_offset =
          windows && path.batch && path.bursts ? SPECULAR_BATCH_COS_OFFSET : expected_offset;
      if (cpu.faults.size() != faults_before + 1 || cpu.faults.back().mcause != 7u ||
          cpu.faults.back().mtval != ip_base + fault_offset)
        failures.push_back(name + ": not exactly one store fault at the refused address");
      // Recovered: the refusal was cleared, a good operation runs.
      cpu.dev.cos_max = 65536u;
      const specular_operands good{65000u, 40u, {255u, 200u, 100u}};
      specular_result result{};
      const int after = specular_compute(&cpu.dev, &good, &result);
      if (after != SPECULAR_OK) failures.push_back(name + ": the next operation returned " + specular_strerror(after));
    }
  });
  EXPECT_TRUE(top.cpu.finished) << "the driver waited for ever on a refusal (the program never ended)";
  EXPECT_FALSE(top.cpu.gave_up) << "the driver polled 10 000 times past a refusal";
  EXPECT_TRUE(failures.empty()) << failures.size() << " failures, the first: " << failures.front();
  EXPECT_EQ(irqs_on_refused_burst, 0u) << "a refused BATCH_COS burst raised an interrupt";
  EXPECT_EQ(top.cpu.shrinks, 0u);
}

// Issue 47: what shading costs a CPU without DMA (read_block/write_block NULL: one
// volatile access per word), counted on the bus. The floor is one store of the cos and
// three loads of pins 24-26 per result; a chunk adds its shared operands (N, R, G, B),
// one wait (a STATUS read when polling) and the acknowledgement. Each BATCH_COS store
// completes when its operation does (the latency is in the store's response: section 6
// of docs/integration.md), so the driver stores a chunk's words back to back and waits
// once. Counted: 1000 pixels in one chunk, polled, on each target.
TEST_P(FirmwareDriver, WordByWordShadeCostsFourAccessesPerResult) {
  const std::size_t count = 1000;
  std::size_t reads = 0, writes = 0;
  int status = 0;
  std::size_t mismatches = 0;
  FirmwareTop& top = elaborate_and_run(GetParam(), [&](FirmwareCpu& cpu) {
    const Core core;
    bind(cpu, false, SPECULAR_WAIT_POLL);
    std::vector<std::uint32_t> cos(count);
    for (std::size_t i = 0; i < count; ++i) cos[i] = 65536u - static_cast<std::uint32_t>(37 * i);
    const std::uint32_t rgb[3] = {255u, 200u, 100u};
    std::vector<std::int32_t> out(3 * count);
    const std::size_t reads_before = cpu.reads, writes_before = cpu.writes;
    status = specular_shade(&cpu.dev, 40u, rgb, cos.data(), count, out.data());
    reads = cpu.reads - reads_before;
    writes = cpu.writes - writes_before;
    for (std::size_t i = 0; i < count; ++i) {
      const Result expected = core.run({cos[i], 40u, {rgb[0], rgb[1], rgb[2]}});
      for (int ch = 0; ch < 3; ++ch) mismatches += out[3 * i + ch] != expected.out[ch];
    }
  });
  EXPECT_TRUE(top.cpu.finished);
  EXPECT_EQ(status, SPECULAR_OK);
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(top.cpu.refused, 0u) << "a back-to-back BATCH_COS store was refused (busy?)";
  // Writes: N, R, G, B, one cos per result, the acknowledgement. Reads: three per result
  // and the one STATUS read of the chunk's wait (DONE is set by the time the last store
  // returns: the CPU's time is past the operation's end). axi has no batch windows
  // (BATCH_CAPACITY 0): per result COS, START, one STATUS read, three results, the
  // acknowledgement.
  if (firmware_targets::is_axi(GetParam())) {
    EXPECT_EQ(writes, 4 + 3 * count);
    EXPECT_EQ(reads, 4 * count);
  } else {
    EXPECT_EQ(writes, 4 + count + 1);
    EXPECT_EQ(reads, 3 * count + 1);
  }
  std::cout << "word-by-word shade: " << static_cast<double>(reads + writes) / count
            << " bus accesses per result (" << writes << " writes, " << reads << " reads for "
            << count << " results)\n";
}

// Under the `literal` policy adder 8 keeps negative values: pins 24-26 and register 9
// after pass 2 go negative, which the driver must sign-extend (S18.13 in a 32-bit word,
// S14.22 in two). Low cos with large n makes A < 0 (spec §1: x < -3).
TEST_P(FirmwareDriver, NegativeResultsUnderLiteralSaturationKeepTheirSign) {
  if (firmware_targets::is_axi(GetParam()))
    GTEST_SKIP() << "the axi IP is verilated for saturation clamp only (its refusal of literal: "
                    "FirmwareDriverAxi.RefusesAConfigurationItWasNotBuiltFor)";
  Config literal;
  literal.saturation = Saturation::literal;
  Tally tally;
  std::size_t negative_out = 0, negative_reg9 = 0;
  FirmwareTop& top = elaborate_and_run(
      GetParam(),
      [&](FirmwareCpu& cpu) {
        const Core core(literal);
        std::mt19937 random(35);
        bind(cpu, true, SPECULAR_WAIT_POLL);
        for (int i = 0; i < 300; ++i) {
          const specular_operands in{static_cast<std::uint32_t>(random() % 60000),
                                     1u + static_cast<std::uint32_t>(random() % 1000),
                                     {static_cast<std::uint32_t>(random() % 256), 255u, 1u}};
          specular_result out{};
          ASSERT_EQ(specular_compute(&cpu.dev, &in, &out), SPECULAR_OK);
          const Result expected = core.run({in.cos, in.n, {in.rgb[0], in.rgb[1], in.rgb[2]}});
          bool equal = out.reg9_pass1 == expected.reg9_pass1 && out.reg9_pass2 == expected.reg9_pass2;
          for (int ch = 0; ch < 3; ++ch) equal = equal && out.out[ch] == expected.out[ch];
          tally.expect(equal, "literal: cos " + std::to_string(in.cos) + " n " + std::to_string(in.n) +
                                  ": reg9 " + std::to_string(out.reg9_pass2) + " vs Core " +
                                  std::to_string(expected.reg9_pass2) + ", out " +
                                  std::to_string(out.out[1]) + " vs " + std::to_string(expected.out[1]));
          negative_out += out.out[1] < 0;
          negative_reg9 += out.reg9_pass2 < 0;
        }
        const std::uint32_t rgb[3] = {255u, 128u, 7u};
        std::vector<std::uint32_t> cos(300);
        for (auto& c : cos) c = static_cast<std::uint32_t>(random() % 30000);
        std::vector<std::int32_t> out(3 * cos.size());
        ASSERT_EQ(specular_shade(&cpu.dev, 900, rgb, cos.data(), cos.size(), out.data()), SPECULAR_OK);
        for (std::size_t i = 0; i < cos.size(); ++i) {
          const Result expected = core.run({cos[i], 900, {rgb[0], rgb[1], rgb[2]}});
          bool equal = true;
          for (int ch = 0; ch < 3; ++ch) equal = equal && out[3 * i + ch] == expected.out[ch];
          tally.expect(equal, "literal batch, cos " + std::to_string(cos[i]));
          negative_out += out[3 * i] < 0;
        }
      },
      literal);
  EXPECT_TRUE(top.cpu.finished);
  EXPECT_EQ(tally.mismatches, 0u) << "of " << tally.operations;
  EXPECT_GT(negative_out, 100u) << "too few negative pins: the sign path is not exercised";
  EXPECT_GT(negative_reg9, 100u);
}

// The `axi` target (issue 46): every access an AXI4-Lite transfer to the verilated IP.
// The suite above runs on it too (its 10 000 operations: the batches pixel by pixel, as
// BATCH_CAPACITY 0 makes the driver run them); these are its own.
// specular_shade() on axi: the driver reads BATCH_CAPACITY 0 from the RTL at init and runs
// one operation per pixel (no window access, nothing refused), polled and by interrupt;
// every pixel bit-equal to Core computed separately.
TEST(FirmwareDriverAxi, ShadeReadsCapacityZeroAndRunsEachPixel) {
  Tally tally;
  std::uint32_t capacity = 0xFFFFFFFFu;
  FirmwareTop& top = elaborate_and_run(Kind::axi, [&](FirmwareCpu& cpu) {
    const Core core;
    std::mt19937 random(46u);
    for (const bool polled : {true, false}) {
      bind(cpu, polled, polled ? SPECULAR_WAIT_POLL : SPECULAR_WAIT_IRQ);
      capacity = cpu.dev.batch_capacity;
      const std::uint32_t rgb[3] = {200u, 17u, 255u};
      std::vector<std::uint32_t> cos(150);
      for (auto& c : cos) c = static_cast<std::uint32_t>(random() % 65537u);
      std::vector<std::int32_t> out(3 * cos.size());
      ASSERT_EQ(specular_shade(&cpu.dev, 12, rgb, cos.data(), cos.size(), out.data()), SPECULAR_OK);
      for (std::size_t i = 0; i < cos.size(); ++i) {
        const Result expected = core.run({cos[i], 12, {rgb[0], rgb[1], rgb[2]}});
        bool equal = true;
        for (int ch = 0; ch < 3; ++ch) equal = equal && out[3 * i + ch] == expected.out[ch];
        tally.expect(equal, "axi shade, cos " + std::to_string(cos[i]));
      }
    }
  });
  EXPECT_TRUE(top.cpu.finished);
  EXPECT_EQ(capacity, 0u) << "BATCH_CAPACITY as the driver read it from specular_ip_axi";
  EXPECT_EQ(tally.operations, 300u);
  EXPECT_EQ(tally.mismatches, 0u);
  EXPECT_EQ(top.cpu.refused, 0u) << "the driver touched a batch window (a hole on axi)";
}

// Each access on axi takes the bus cycles of the IP's timing (docs/rtl_ip.md, "Timing"),
// counted as this transactor drives it (AW and W together, READY high at once): a read
// 2 (AR taken, R the cycle after), a write 3 (AW and W held, the write done, B), a START
// 7 (held, done at the 2nd edge, B with the results at the 4th edge after, then taken).
TEST(FirmwareDriverAxi, EachAccessTakesTheCyclesOfTheIpTiming) {
  std::vector<double> cycles;
  elaborate_and_run(Kind::axi, [&](FirmwareCpu& cpu) {
    auto timed = [&](auto&& access) {
      const sc_time before = sc_core::sc_time_stamp() + cpu.keeper.get_local_time();
      access();
      const sc_time after = sc_core::sc_time_stamp() + cpu.keeper.get_local_time();
      cycles.push_back((after - before - sc_time(2, SC_NS)) / period);  // less the CPU's 2 ns
    };
    timed([&] { FirmwareCpu::read32(&cpu, ip_base + SPECULAR_STATUS_OFFSET); });
    timed([&] { FirmwareCpu::write32(&cpu, ip_base + SPECULAR_COS_OFFSET, 30000u); });
    timed([&] { FirmwareCpu::write32(&cpu, ip_base + SPECULAR_N_OFFSET, 7u); });
    timed([&] { FirmwareCpu::write32(&cpu, ip_base + SPECULAR_CONTROL_OFFSET, SPECULAR_CONTROL_START_MASK); });
    timed([&] { FirmwareCpu::read32(&cpu, ip_base + SPECULAR_STATUS_OFFSET); });
  });
  ASSERT_EQ(cycles.size(), 5u);
  EXPECT_DOUBLE_EQ(cycles[0], 2.0) << "read";
  EXPECT_DOUBLE_EQ(cycles[1], 3.0) << "write";
  EXPECT_DOUBLE_EQ(cycles[2], 3.0) << "write";
  EXPECT_DOUBLE_EQ(cycles[3], 7.0) << "START";
  EXPECT_DOUBLE_EQ(cycles[4], 2.0) << "read";
}

// A refusal on axi (SLVERR, DECERR) comes back as the TLM response SpecularTarget's class
// comment gives for its cause, and nothing is stored: out of range and reserved bits
// generic, a read-only row a command error, a hole (the batch window here) an address error.
TEST(FirmwareDriverAxi, RefusalsComeBackAsTheResponsesOfTheirCause) {
  std::vector<tlm::tlm_response_status> responses;
  std::uint32_t n_after = 0, config_after = 0;
  elaborate_and_run(Kind::axi, [&](FirmwareCpu& cpu) {
    auto write = [&](std::uint32_t offset, std::uint32_t value) {
      FirmwareCpu::write32(&cpu, ip_base + offset, value);
      responses.push_back(cpu.last_response);
    };
    write(SPECULAR_N_OFFSET, 7u);
    write(SPECULAR_N_OFFSET, 1001u);
    write(SPECULAR_CONTROL_OFFSET, 2u);
    write(SPECULAR_CONFIG_OFFSET, 0u);
    write(SPECULAR_BATCH_COS_OFFSET, 100u);
    n_after = FirmwareCpu::read32(&cpu, ip_base + SPECULAR_N_OFFSET);
    config_after = FirmwareCpu::read32(&cpu, ip_base + SPECULAR_CONFIG_OFFSET);
  });
  ASSERT_EQ(responses.size(), 5u);
  EXPECT_EQ(responses[0], tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(responses[1], tlm::TLM_GENERIC_ERROR_RESPONSE) << "N 1001";
  EXPECT_EQ(responses[2], tlm::TLM_GENERIC_ERROR_RESPONSE) << "CONTROL reserved bit";
  EXPECT_EQ(responses[3], tlm::TLM_COMMAND_ERROR_RESPONSE) << "CONFIG is read-only";
  EXPECT_EQ(responses[4], tlm::TLM_ADDRESS_ERROR_RESPONSE) << "BATCH_COS is a hole on axi";
  EXPECT_EQ(n_after, 7u) << "the refused N was stored";
  EXPECT_EQ(config_after, 0x080D1000u) << "CONFIG of the default device";
}

// The transactor's seeded random stalls (the suite above runs whole with them: axi_stalled)
// add cycles and change no answer; a stall chance the transfer limit cannot absorb is
// refused by name.
TEST(FirmwareDriverAxi, RandomStallsAddCyclesAndChangeNoAnswer) {
  std::size_t wrong = 0;
  FirmwareTop& top = elaborate_and_run(Kind::axi_stalled, [&](FirmwareCpu& cpu) {
    for (int i = 0; i < 200; ++i) wrong += FirmwareCpu::read32(&cpu, ip_base + SPECULAR_ID_OFFSET) != 0x00059965u;
  });
  EXPECT_EQ(wrong, 0u);
  auto& axi = static_cast<SpecularAxiTarget&>(*top.target);
  EXPECT_GT(axi.cycles(), 200u * 2u + 100u) << "a read takes 2 cycles unstalled: too few stalls";
  try {
    axi.stall_at_random(1, 51);
    ADD_FAILURE() << "a stall chance of 51 % was accepted";
  } catch (const std::invalid_argument& refused) {
    EXPECT_NE(std::string(refused.what()).find("51"), std::string::npos) << refused.what();
    EXPECT_NE(std::string(refused.what()).find("0..50"), std::string::npos) << refused.what();
  }
}

// The IP is verilated for one configuration: another is refused by name, not run wrong.
TEST(FirmwareDriverAxi, AConfigTheIpWasNotBuiltForIsRefusedByName) {
  Config literal;
  literal.saturation = Saturation::literal;
  try {
    SpecularAxiTarget target("axi_literal", literal);
    ADD_FAILURE() << "saturation literal was accepted";
  } catch (const std::invalid_argument& refused) {
    const std::string what = refused.what();
    EXPECT_NE(what.find("literal"), std::string::npos) << what;
    EXPECT_NE(what.find("clamp"), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FirmwareDriver,
                         testing::Values(Kind::lt, Kind::pin, Kind::rtl, Kind::rtl_sync, Kind::axi,
                                         Kind::axi_stalled),
                         kind_name);

// ---- Arguments, without SystemC: a register file in C++ that records the writes ----

struct FakeIp {
  std::map<std::uint32_t, std::uint32_t> regs{
      {SPECULAR_ID_OFFSET, device_id},
      {SPECULAR_VERSION_OFFSET, map_version},
      {SPECULAR_CONFIG_OFFSET, config_word(Config{})}};
  std::vector<std::uint32_t> writes;  ///< offsets written, in order
  std::vector<std::uint32_t> values;  ///< ... and the values
  static std::uint32_t read32(void* context, std::uintptr_t address) {
    return static_cast<FakeIp*>(context)->regs[static_cast<std::uint32_t>(address - ip_base)];
  }
  static void write32(void* context, std::uintptr_t address, std::uint32_t value) {
    static_cast<FakeIp*>(context)->writes.push_back(static_cast<std::uint32_t>(address - ip_base));
    static_cast<FakeIp*>(context)->values.push_back(value);
  }
  specular_bus bus() {
    specular_bus b{};
    b.read32 = read32;
    b.write32 = write32;
    b.context = this;
    return b;
  }
};

TEST(FirmwareDriverArguments, EachBadArgumentIsNamedAndNothingIsWritten) {
  FakeIp ip;
  const specular_bus bus = ip.bus();
  specular_dev dev;
  ASSERT_EQ(specular_init(&dev, ip_base, &bus), SPECULAR_OK);
  ip.writes.clear();
  const specular_operands good{65536, 1000, {255, 255, 255}};
  struct Case {
    specular_operands in;
    int expected;
  };
  const Case cases[] = {
      {{0, 0, {0, 0, 0}}, SPECULAR_ERR_N},          {{0, 1001, {0, 0, 0}}, SPECULAR_ERR_N},
      {{65537, 1, {0, 0, 0}}, SPECULAR_ERR_COS},    {{0xFFFFFFFFu, 1, {0, 0, 0}}, SPECULAR_ERR_COS},
      {{0, 1, {256, 0, 0}}, SPECULAR_ERR_RGB},      {{0, 1, {0, 256, 0}}, SPECULAR_ERR_RGB},
      {{0, 1, {0, 0, 256}}, SPECULAR_ERR_RGB},
  };
  for (const Case& c : cases) {
    specular_result out{};
    EXPECT_EQ(specular_compute(&dev, &c.in, &out), c.expected) << c.in.cos << " " << c.in.n;
  }
  EXPECT_EQ(specular_compute(&dev, nullptr, nullptr), SPECULAR_ERR_NULL);
  EXPECT_EQ(specular_compute(nullptr, &good, nullptr), SPECULAR_ERR_NULL);
  EXPECT_EQ(specular_start(&dev, 65537), SPECULAR_ERR_COS);
  const std::uint32_t rgb_bad[3] = {1, 2, 300};
  EXPECT_EQ(specular_set_shared(&dev, 5, rgb_bad), SPECULAR_ERR_RGB);

  const std::uint32_t rgb[3] = {10, 20, 30};
  std::vector<std::uint32_t> cos(2000, 65536);
  std::vector<std::int32_t> out(3 * cos.size());
  cos[1500] = 65537;
  EXPECT_EQ(specular_shade(&dev, 10, rgb, cos.data(), cos.size(), out.data()), SPECULAR_ERR_COS);
  EXPECT_EQ(dev.bad_index, 1500u);
  EXPECT_EQ(specular_shade(&dev, 10, rgb, cos.data(), 0, out.data()), SPECULAR_ERR_COUNT);
  EXPECT_EQ(specular_shade(&dev, 0, rgb, cos.data(), 1, out.data()), SPECULAR_ERR_N);
  EXPECT_EQ(specular_shade(&dev, 10, rgb_bad, cos.data(), 1, out.data()), SPECULAR_ERR_RGB);
  EXPECT_EQ(specular_shade(&dev, 10, rgb, nullptr, 1, out.data()), SPECULAR_ERR_NULL);
  EXPECT_TRUE(ip.writes.empty()) << ip.writes.size() << " writes, the first at " << ip.writes.front();
  // The edges are accepted.
  specular_result result{};
  ip.regs[SPECULAR_STATUS_OFFSET] = SPECULAR_STATUS_DONE_MASK;
  EXPECT_EQ(specular_compute(&dev, &good, &result), SPECULAR_OK);
  const specular_operands low{0, 1, {0, 0, 0}};
  EXPECT_EQ(specular_compute(&dev, &low, &result), SPECULAR_OK);
  EXPECT_STRNE(specular_strerror(SPECULAR_ERR_N), specular_strerror(SPECULAR_ERR_COS));
}

TEST(FirmwareDriverArguments, InitRefusesAnotherDeviceOrMajorVersion) {
  FakeIp ip;
  const specular_bus bus = ip.bus();
  specular_dev dev;
  EXPECT_EQ(specular_init(nullptr, ip_base, &bus), SPECULAR_ERR_NULL);
  ip.regs[SPECULAR_VERSION_OFFSET] = 0x00020000u;
  EXPECT_EQ(specular_init(&dev, ip_base, &bus), SPECULAR_ERR_VERSION);
  ip.regs[SPECULAR_ID_OFFSET] = 0x12345678u;
  EXPECT_EQ(specular_init(&dev, ip_base, &bus), SPECULAR_ERR_NOT_SPECULAR);
}

TEST(FirmwareDriverArguments, TheRangesComeFromConfig) {
  FakeIp ip;
  Config narrow;
  narrow.widths.cos_frac_bits = 12;
  narrow.widths.rgb_bits = 6;
  ip.regs[SPECULAR_CONFIG_OFFSET] = config_word(narrow);
  const specular_bus bus = ip.bus();
  specular_dev dev;
  ASSERT_EQ(specular_init(&dev, ip_base, &bus), SPECULAR_OK);
  EXPECT_EQ(dev.cos_max, 4096u);
  EXPECT_EQ(dev.rgb_max, 63u);
  ip.writes.clear();
  const specular_operands too_bright{4096, 1, {64, 0, 0}};
  EXPECT_EQ(specular_compute(&dev, &too_bright, nullptr), SPECULAR_ERR_RGB);
  const specular_operands too_wide{4097, 1, {63, 0, 0}};
  EXPECT_EQ(specular_compute(&dev, &too_wide, nullptr), SPECULAR_ERR_COS);
  EXPECT_TRUE(ip.writes.empty());
}

// The two interrupt hooks: notify only sets the flag (no bus access: a simulator's
// callback may not make one); the handler, for an ISR on the level, also acknowledges
// with the one write that makes the level fall (W1C of STATUS.DONE).
TEST(FirmwareDriverArguments, TheIrqHandlerAcknowledgesAndNotifyOnlySetsTheFlag) {
  FakeIp ip;
  const specular_bus bus = ip.bus();
  specular_dev dev;
  ASSERT_EQ(specular_init(&dev, ip_base, &bus), SPECULAR_OK);
  ip.writes.clear();
  ip.values.clear();
  EXPECT_EQ(dev.irq_pending, 0u);
  specular_irq_notify(&dev);
  EXPECT_EQ(dev.irq_pending, 1u);
  EXPECT_TRUE(ip.writes.empty());
  dev.irq_pending = 0u;
  specular_irq_handler(&dev);
  EXPECT_EQ(dev.irq_pending, 1u);
  ASSERT_EQ(ip.writes.size(), 1u);
  EXPECT_EQ(ip.writes[0], offset_of(Reg::status));
  EXPECT_EQ(ip.values[0], status_bits::done);
  specular_irq_notify(nullptr);  // no crash
  specular_irq_handler(nullptr);
}

}  // namespace
}  // namespace specular
