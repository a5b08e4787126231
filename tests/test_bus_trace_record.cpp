// Records the IP's bus accesses on the `axi` TLM target (issue 60, must-have 2), for the
// RTL SoC's replay bench to replay into specular_ip_axi at a non-zero base and compare
// every read value and response: the bare-metal example's ELF on the RV32 hart
// (tests/support/rv32_hart.h; polled, through a PLIC, done_irq straight to the hart) and
// the driver's 10 000-operation run (tests/support/firmware_driver_cpu.h, the program of
// FirmwareDriver.TenThousandOperationsEqualCorePolledAndByInterrupt). `axi` because its
// register view is specular_ip_axi's (BATCH_CAPACITY 0, no windows): firmware recorded on
// lt would take the windows the RTL IP refuses. tests/support/bus_trace_recorder.h sits
// between the CPU and the target and writes the trace; every access is also put to an lt
// target at the same time and the answers compared (off BATCH_CAPACITY and the windows
// they must be equal), so the trace is the TLM model's answer, not only the RTL's.
// A trace is written only by a run that passed (the example's PASS line, the driver's
// results equal to Core): into the test's scratch folder, and into
// $SPECULAR_BUS_TRACE_DIR/<name>.trace when that is set (tests/CMakeLists.txt sets it for
// ctest, and names these tests fixture specular_bus_traces for the replay).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "specular/tlm/lt_target.h"
#include "support/bus_trace_recorder.h"
#include "support/firmware_driver_cpu.h"
#include "support/rv32_example_link.h"
#include "support/rv32_hart.h"
#include "support/scratch.h"
#include "support/subprocess.h"

namespace specular {
namespace {

using firmware_targets::Kind;
using testing_support::BusTraceRecorder;
using Beat = BusTraceRecorder::Beat;

/// $SPECULAR_BUS_TRACE_DIR/name, or empty when the variable is unset.
std::filesystem::path shared_trace(const std::string& name) {
  const char* dir = std::getenv("SPECULAR_BUS_TRACE_DIR");
  if (dir == nullptr || dir[0] == '\0') return {};
  return std::filesystem::path(dir) / name;
}

/// A previous run's trace goes first: a run that fails leaves none for the replay.
void remove_shared(const std::string& name) {
  const std::filesystem::path path = shared_trace(name);
  if (!path.empty()) std::filesystem::remove(path);
}

/// The recorder between a CPU and its target, cross-checked on an lt target; the
/// recorder is kept in `recorder` (alive until exit, as SystemC wants).
firmware_targets::Wiring recording(std::unique_ptr<BusTraceRecorder>& recorder) {
  return [&recorder](tlm::tlm_initiator_socket<32>& cpu, SpecularTarget& target) {
    recorder = std::make_unique<BusTraceRecorder>(
        "recorder", std::make_unique<SpecularLtTarget>("lt_check", Config{}, target.clock_period()));
    cpu.bind(recorder->target_socket);
    recorder->initiator_socket.bind(target.socket);
  };
}

/// Every access had its beats, and lt answered every beat off the batch rows alike.
void expect_recorded_and_equal_on_lt(const BusTraceRecorder& recorder) {
  EXPECT_EQ(recorder.unrecorded(), 0u) << "the first: " << (recorder.notes().empty() ? "" : recorder.notes()[0]);
  const auto& check = recorder.check();
  EXPECT_EQ(check.beats, recorder.beats().size());
  EXPECT_EQ(check.differences, 0u) << "the first: "
                                   << (check.first_differences.empty() ? "" : check.first_differences[0]);
  std::cout << "cross-check on lt: " << check.beats << " beats, " << check.differences
            << " different off BATCH_CAPACITY and the windows; " << check.on_batch_rows
            << " on them, of which " << check.on_batch_rows_different << " different\n";
}

/// Writes the trace if the test has passed so far (scratch folder, and the shared path).
void save(const BusTraceRecorder& recorder, const std::string& name) {
  if (testing::Test::HasFailure()) return;
  recorder.write(testing_support::scratch_file(name));
  const std::filesystem::path shared = shared_trace(name);
  if (!shared.empty()) recorder.write(shared);
  std::cout << name << ": " << recorder.beats().size() << " lines"
            << (shared.empty() ? std::string() : ", also " + shared.string()) << "\n";
}

/// specular_init's five accesses on the default axi IP: ID, VERSION, CONFIG (U1.16 cos,
/// S.13 outputs, 8-bit RGB), BATCH_CAPACITY 0, then STATUS's DONE and ERROR cleared (W1C).
const Beat init_beats[] = {{0, 0x000, 0x00059965u, 0xF, 0}, {0, 0x004, 0x00010001u, 0xF, 0},
                           {0, 0x008, 0x080D1000u, 0xF, 0}, {0, 0x014, 0u, 0xF, 0},
                           {1, 0x00C, 0x6u, 0xF, 0}};

std::size_t count_inits(const std::vector<Beat>& beats) {
  std::size_t inits = 0;
  for (std::size_t i = 0; i + 5 <= beats.size(); ++i) {
    bool all = true;
    for (std::size_t k = 0; k < 5; ++k) all = all && beats[i + k] == init_beats[k];
    inits += all;
  }
  return inits;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---- The bare-metal example's ELF ---------------------------------------------------

class BusTraceRecordExample : public testing::TestWithParam<std::string> {};

// Passes only if the example printed its PASS line and exited 0; its refused store
// (N = 1001) is the trace's one refusal, SLVERR; it starts with specular_init's accesses.
TEST_P(BusTraceRecordExample, TheElfOnAxiPassesAndItsAccessesAreRecorded) {
  const auto start = std::chrono::steady_clock::now();
  const std::string variant = GetParam(), name = "example_" + variant + ".trace";
  remove_shared(name);
  const std::filesystem::path elf = testing_support::link_rv32_example(variant);
  ASSERT_TRUE(std::filesystem::exists(elf));
  static std::unique_ptr<BusTraceRecorder> recorder;
  static std::unique_ptr<firmware_targets::Rv32Hart> hart;  // alive until exit, as SystemC wants
  hart = std::make_unique<firmware_targets::Rv32Hart>("hart", Kind::axi,
                                                      variant == "irq" ? firmware_targets::IrqWiring::plic
                                                                       : firmware_targets::IrqWiring::hart,
                                                      elf.string(),
                                                      recording(recorder));
  sc_core::sc_start();
  std::cout << hart->console;
  ASSERT_TRUE(hart->exited) << "the program did not exit: " << hart->error << " at pc " << hart->pc;
  ASSERT_EQ(hart->exit_code, 0);
  ASSERT_NE(hart->console.find("\nPASS: every result equal to Core\n"), std::string::npos);
  EXPECT_EQ(hart->faults, 1u);
  if (variant != "poll") {
    EXPECT_GE(hart->interrupts, 1u);
  }

  const std::vector<Beat>& beats = recorder->beats();
  ASSERT_GE(beats.size(), 5u);
  EXPECT_EQ(count_inits(beats), 1u) << "specular_init's accesses, once, as the trace's first lines";
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(beats[k], init_beats[k]) << "line " << k + 1;
  std::size_t refused = 0;
  for (const Beat& beat : beats) {
    if (beat.resp == 0) continue;
    ++refused;
    EXPECT_EQ(beat, (Beat{1, 0x024, 1001u, 0xF, 2})) << BusTraceRecorder::line(beat);
  }
  EXPECT_EQ(refused, 1u) << "the example's one refused store, N = 1001 (SLVERR)";
  expect_recorded_and_equal_on_lt(*recorder);
  EXPECT_EQ(recorder->check().on_batch_rows, 1u) << "BATCH_CAPACITY, read once by specular_init";
  EXPECT_EQ(recorder->check().on_batch_rows_different, 1u) << "0 on axi, 1024 on lt";
  save(*recorder, name);
  std::cout << "(" << hart->instructions << " instructions, " << hart->interrupts << " interrupts; "
            << seconds_since(start) << " s)\n";
}

INSTANTIATE_TEST_SUITE_P(Builds, BusTraceRecordExample,
                         testing::Values(std::string("poll"), std::string("irq"), std::string("irq_direct")),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

// ---- The driver's 10 000 operations ---------------------------------------------------

// The program of FirmwareDriver.TenThousandOperationsEqualCorePolledAndByInterrupt, its
// results checked against Core as there; on axi nothing is refused and there are no
// bursts (BATCH_CAPACITY 0: the driver runs its batches pixel by pixel), so every line is
// a whole word, OKAY; four specular_init runs, each reading BATCH_CAPACITY once.
TEST(BusTraceRecord, TheDriversTenThousandOperationsOnAxiAreRecorded) {
  const auto start = std::chrono::steady_clock::now();
  const std::string name = "driver_10000.trace";
  remove_shared(name);
  static std::unique_ptr<BusTraceRecorder> recorder;
  firmware_driver::TenThousandRun run;
  firmware_driver::FirmwareTop& top = firmware_driver::elaborate_and_run(
      Kind::axi, [&](firmware_driver::FirmwareCpu& cpu) { firmware_driver::ten_thousand_operations(cpu, run); },
      Config{}, recording(recorder));
  firmware_driver::expect_ten_thousand_passed(top, run);
  ASSERT_FALSE(HasFailure()) << "the run failed: no trace";

  const std::vector<Beat>& beats = recorder->beats();
  EXPECT_EQ(count_inits(beats), 4u);
  ASSERT_GE(beats.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(beats[k], init_beats[k]) << "line " << k + 1;
  std::size_t not_okay = 0, not_whole = 0;
  for (const Beat& beat : beats) {
    not_okay += beat.resp != 0;
    not_whole += beat.strb != 0xF;
  }
  EXPECT_EQ(not_okay, 0u);
  EXPECT_EQ(not_whole, 0u);
  // Every operation on axi takes at least its COS written, START and three results read.
  EXPECT_GE(beats.size(), 5u * run.tally.operations);
  expect_recorded_and_equal_on_lt(*recorder);
  EXPECT_EQ(recorder->check().on_batch_rows, 4u);
  EXPECT_EQ(recorder->check().on_batch_rows_different, 4u);
  save(*recorder, name);
  std::cout << run.tally.operations << " operations equal to Core (" << seconds_since(start) << " s)\n";
}

// ---- The recorder itself, access by access --------------------------------------------

// Each shape of access becomes the beats the axi target puts on the bus (values from the
// register map and docs/rtl_ip.md's timing, not from the recorder), the delay passes
// through unchanged (a read 2 bus cycles, a write 3), and what has no beat form is counted,
// not written.
TEST(BusTraceRecorder, EachAccessBecomesItsBeatsAndItsDelayPassesThrough) {
  static std::unique_ptr<BusTraceRecorder> recorder;
  std::vector<double> cycles;
  firmware_driver::elaborate_and_run(
      Kind::axi,
      [&](firmware_driver::FirmwareCpu& cpu) {
        auto access = [&](tlm::tlm_command command, std::uint32_t offset, std::vector<std::uint8_t> bytes) {
          const sc_core::sc_time before = sc_core::sc_time_stamp() + cpu.keeper.get_local_time();
          cpu.access(command, firmware_driver::ip_base + offset, bytes.data(), bytes.size());
          const sc_core::sc_time after = sc_core::sc_time_stamp() + cpu.keeper.get_local_time();
          cycles.push_back((after - before - sc_core::sc_time(2, sc_core::SC_NS)) / firmware_driver::period);
        };
        const auto read = tlm::TLM_READ_COMMAND;
        const auto write = tlm::TLM_WRITE_COMMAND;
        access(read, 0x000, std::vector<std::uint8_t>(4));     // ID
        access(write, 0x024, {7, 0, 0, 0});                    // N = 7
        access(write, 0x024, {0xE9, 0x03, 0, 0});              // N = 1001: SLVERR
        access(read, 0x7FFC, std::vector<std::uint8_t>(4));    // a hole: DECERR
        access(write, 0x02C, {0x7F});                          // G's byte lane 0
        access(write, 0x02E, {0x01, 0x00});                    // G's lanes 2-3: G = 0x1007F, SLVERR
        access(write, 0x020, {100, 0, 0, 0, 9, 0, 0, 0});      // COS, N in one 8-byte write
        access(read, 0x000, std::vector<std::uint8_t>(1));     // a byte of ID: no beat form
        access(read, 0x014, std::vector<std::uint8_t>(4));     // BATCH_CAPACITY
        access(read, 0x0A0, std::vector<std::uint8_t>(12));    // RESULTS: three beats
      },
      Config{}, recording(recorder));
  const std::vector<std::string> expected = {
      "0 0000 00059965 f 0", "1 0024 00000007 f 0", "1 0024 000003e9 f 2", "0 7ffc 00000000 f 3",
      "1 002c 0000007f 1 0", "1 002e 00010000 c 2", "1 0020 00000064 f 0", "1 0024 00000009 f 0",
      "0 0014 00000000 f 0", "0 00a0 00000000 f 0", "0 00a4 00000000 f 0", "0 00a8 00000000 f 0"};
  std::vector<std::string> lines;
  for (const Beat& beat : recorder->beats()) lines.push_back(BusTraceRecorder::line(beat));
  EXPECT_EQ(lines, expected);
  EXPECT_EQ(recorder->unrecorded(), 1u);
  ASSERT_FALSE(recorder->notes().empty());
  EXPECT_EQ(recorder->notes()[0], "a 1-byte read at 0x0: a sub-word read");
  ASSERT_EQ(cycles.size(), 10u);
  EXPECT_DOUBLE_EQ(cycles[0], 2.0) << "a read through the recorder";
  EXPECT_DOUBLE_EQ(cycles[1], 3.0) << "a write through the recorder";
  // lt answers every beat alike but BATCH_CAPACITY (1024 there).
  EXPECT_EQ(recorder->check().differences, 0u)
      << (recorder->check().first_differences.empty() ? "" : recorder->check().first_differences[0]);
  EXPECT_EQ(recorder->check().on_batch_rows, 1u);
  EXPECT_EQ(recorder->check().on_batch_rows_different, 1u);
  const std::filesystem::path file = testing_support::scratch_file("directed.trace");
  recorder->write(file);
  std::string joined;
  for (const std::string& l : expected) joined += l + "\n";
  EXPECT_EQ(testing_support::slurp(file), joined);
}

}  // namespace
}  // namespace specular
