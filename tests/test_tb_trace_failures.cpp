// specular_tb --trace-failures DIR (issue 27): a failure is planted through the
// testbench's result tap (testbench.h: the run sees a wrong result for chosen
// operations); each failing operation's waveform, with the operation before it, is
// written to DIR/op_INDEX.vcd, at most --trace-failures-max of them, and the report
// names them. Each file is opened here and compared with the same two operations in
// the run's own whole trace (a second run, as a user makes it): the same values and
// edges, times shifted by a constant. In process (one elaboration per test).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/scratch.h"
#include "support/subprocess.h"
#include "support/vcd.h"
#include "support/vcd_stretch.h"
#include "testbench.h"

namespace fs = std::filesystem;
using namespace specular::testing_support;

namespace {

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
constexpr long long period_ps = 10000;

struct Planted {
  int status = -1;
  std::string out, err;
};

/// Runs `args` in process with operations `failing` (indices from 0) given a wrong
/// output code, as a broken model would.
Planted run_planted(const std::vector<std::string>& args, const std::set<std::size_t>& failing) {
  std::size_t index = 0;
  const specular::tb::ResultTap tap = [&](const specular::tb::Stimulus&, specular::Result& result,
                                          double&) {
    if (failing.count(index++)) result.out[0] += specular::code_t{1} << 20;  // 128 units of R
  };
  std::ostringstream out, err;
  Planted p;
  p.status = specular::tb::run_testbench(args, out, err, tap);
  p.out = out.str();
  p.err = err.str();
  return p;
}

/// The failing operation k's file against the whole run's operations k-1 and k.
void expect_replay_is_the_run(const Vcd& replay, const Vcd& whole, std::size_t k, bool synchronous) {
  const long long quarter = period_ps / 4;
  const auto rises27 = whole.rises(var_named(whole, "pin27_start"));
  ASSERT_GT(rises27.size(), k);
  // Operation k-1's inputs begin the file; two rises of 35 (k-1 and k) end it.
  const long long run_from = rises27[k - 1] + (synchronous ? 0 : -quarter);
  const long long from = first_time(replay);
  const auto dones = replay.rises(var_named(replay, "pin35_done"));
  ASSERT_EQ(dones.size(), 2u);
  const long long shift = from - run_from;
  EXPECT_EQ(shift % period_ps, 0) << "the replay keeps the clock's phase";
  // Before operation 0 the run's registers held their power-on zeros, the replay's
  // what the run left in them (a reset clears only the control unit): operation 1's
  // file (0 and 1) has the run's pins; from operation 2 on (k-2 replayed untraced
  // first) every net is the run's.
  EXPECT_GT(expect_same_stretch(replay, whole, shift, from, dones.back(), k == 1 ? "pin" : ""), 20u);
}

void expect_failure_traces(const std::string& model, bool synchronous) {
  const fs::path dir = scratch_dir();
  const fs::path traces = dir / "failures";
  // The run's own whole trace, for comparison.
  const fs::path whole_path = dir / "whole.vcd";
  const Outcome whole_run = run_command("'" + tb + "' --model " + model +
                                            " --random 30 --seed 3 --vcd '" + whole_path.string() + "'",
                                        dir, "whole");
  ASSERT_EQ(whole_run.status, 0) << whole_run.err;
  const Vcd whole = parse_vcd(slurp(whole_path));

  // Operations 1 (its predecessor is the first after reset), 9 and 20 fail; two files.
  const Planted p = run_planted({"--model", model, "--random", "30", "--seed", "3",
                                 "--trace-failures", traces.string(), "--trace-failures-max", "2"},
                                {1, 9, 20});
  EXPECT_EQ(p.status, 1) << p.err;  // out of tolerance
  const fs::path op1 = traces / "op_1.vcd", op9 = traces / "op_9.vcd";
  EXPECT_NE(p.out.find(op1.string()), std::string::npos) << p.out;
  EXPECT_NE(p.out.find(op9.string()), std::string::npos) << p.out;
  EXPECT_NE(p.out.find("1 more failing operation(s) not traced"), std::string::npos) << p.out;
  EXPECT_FALSE(fs::exists(traces / "op_20.vcd"));
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(traces)) files += entry.is_regular_file();
  EXPECT_EQ(files, 2u);

  ASSERT_TRUE(fs::exists(op1) && fs::exists(op9));
  expect_replay_is_the_run(parse_vcd(slurp(op1)), whole, 1, synchronous);
  expect_replay_is_the_run(parse_vcd(slurp(op9)), whole, 9, synchronous);
}

TEST(TraceFailures, PinFailingOperationsWaveforms) { expect_failure_traces("pin", false); }

#ifdef SPECULAR_HAS_RTL_TWIN
TEST(TraceFailures, RtlFailingOperationsWaveforms) { expect_failure_traces("rtl", false); }
TEST(TraceFailures, RtlSyncFailingOperationsWaveforms) { expect_failure_traces("rtl-sync", true); }
#endif

// Failures at the first two operations of the second batch (4096 operations a batch,
// run_models.h): the replay keeps the gap the batch boundary made in the run.
TEST(TraceFailures, PinFailuresAcrossABatchBoundary) {
  const fs::path dir = scratch_dir();
  const fs::path traces = dir / "failures", window_path = dir / "window.vcd";
  const Outcome window_run = run_command("'" + tb + "' --random 4100 --vcd '" + window_path.string() +
                                             "' --trace-ops 4093:5",
                                         dir, "window");
  ASSERT_EQ(window_run.status, 0) << window_run.err;
  const Vcd window = parse_vcd(slurp(window_path));
  const Planted p = run_planted({"--random", "4100", "--trace-failures", traces.string()}, {4096, 4097});
  EXPECT_EQ(p.status, 1);
  for (const std::size_t k : {4096u, 4097u}) {
    const fs::path file = traces / ("op_" + std::to_string(k) + ".vcd");
    ASSERT_TRUE(fs::exists(file));
    const Vcd replay = parse_vcd(slurp(file));
    // The window's pin 27 rises are operations 4093.. in order.
    const auto rises27 = window.rises(var_named(window, "pin27_start"));
    ASSERT_EQ(rises27.size(), 5u);
    const long long run_from = rises27[k - 1 - 4093] - period_ps / 4;
    const long long from = first_time(replay);
    const auto dones = replay.rises(var_named(replay, "pin35_done"));
    ASSERT_EQ(dones.size(), 2u);
    EXPECT_GT(expect_same_stretch(replay, window, from - run_from, from, dones.back()), 50u) << k;
  }
}

// No failure: no file, the report names none, the JSON has no failure_traces.
TEST(TraceFailures, PassingRunWritesNothing) {
  const fs::path traces = scratch_dir() / "failures";
  const Planted p = run_planted({"--random", "30", "--trace-failures", traces.string(),
                                 "--format", "json"}, {});
  EXPECT_EQ(p.status, 0) << p.err;
  EXPECT_TRUE(fs::is_empty(traces));
  EXPECT_EQ(p.out.find("failure_traces"), std::string::npos);
}

// A failure in JSON: the summary lists the file.
TEST(TraceFailures, JsonNamesTheFiles) {
  const fs::path traces = scratch_dir() / "failures";
  const Planted p = run_planted({"--random", "12", "--trace-failures", traces.string(),
                                 "--format", "json"}, {5});
  EXPECT_EQ(p.status, 1) << p.err;
  const nlohmann::json doc = nlohmann::json::parse(p.out);  // issue 25: summary by nlohmann-json
  EXPECT_EQ(doc["summary"]["failure_traces"], nlohmann::json::array({(traces / "op_5.vcd").string()}))
      << p.out;
  EXPECT_EQ(doc["summary"]["failure_traces_left_out"], 0);
  EXPECT_TRUE(fs::exists(traces / "op_5.vcd"));
}

}  // namespace
