// specular_tb --vcd FILE --trace-ops FIRST:COUNT (issue 27): the window holds the same
// values and edges as the same stretch of a whole-run VCD, at the same instants, from
// operation FIRST's inputs (a quarter period before its start edge; the synchronous
// variant: its start level) to operation FIRST+COUNT-1's rising edge of 35; nothing
// of the operations before it. Each model runs as a user runs it (a subprocess).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/scratch.h"
#include "support/subprocess.h"
#include "support/vcd.h"
#include "support/vcd_stretch.h"

namespace fs = std::filesystem;
using namespace specular::testing_support;

namespace {

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
constexpr long long period_ps = 10000;  // the default --clock-period

Vcd run_vcd(const fs::path& dir, const std::string& model, const std::string& file,
            const std::string& extra) {
  const fs::path vcd = dir / file;
  const Outcome r = run_command("'" + tb + "' --model " + model + " --random 40 --seed 7 --vcd '" +
                                    vcd.string() + "' " + extra,
                                dir, file);
  EXPECT_EQ(r.status, 0) << r.err;
  return parse_vcd(slurp(vcd));
}

void expect_window_is_the_stretch(const std::string& model, bool synchronous) {
  const fs::path dir = scratch_dir();
  const long long first = 17, count = 4;
  const Vcd whole = run_vcd(dir, model, "whole.vcd", "");
  const Vcd window = run_vcd(dir, model, "window.vcd", "--trace-ops 17:4");

  // Where operation 17 begins in the whole run: a quarter period before its start
  // edge, as its inputs lead. Pin 27 rises at the start edge (the synchronous
  // variant: with the inputs, a quarter period before the edge that samples it); its
  // rises count the operations from 0.
  const auto rises27 = whole.rises(var_named(whole, "pin27_start"));
  ASSERT_GT(rises27.size(), static_cast<std::size_t>(first + count));
  const long long quarter = period_ps / 4;
  const auto start_edge = [&](long long op) { return rises27[op] + (synchronous ? quarter : 0); };
  const long long from = start_edge(first) - quarter;
  EXPECT_EQ(first_time(window), from);

  // It ends at operation 20's 35↑: four rises of 35 in the window, the last of them
  // 2.5 periods (the synchronous variant: 2) after its start.
  const auto dones = window.rises(var_named(window, "pin35_done"));
  ASSERT_EQ(dones.size(), static_cast<std::size_t>(count));
  const long long latency = synchronous ? 2 * period_ps : 5 * period_ps / 2;
  EXPECT_EQ(dones.back(), start_edge(first + count - 1) + latency);

  EXPECT_GT(expect_same_stretch(window, whole, 0, from, dones.back()), 100u);
  // Nothing before the window: the window's variables are the whole run's.
  EXPECT_EQ(window.vars.size(), whole.vars.size());
}

TEST(TraceWindow, PinWindowIsTheWholeRunsStretch) { expect_window_is_the_stretch("pin", false); }

#ifdef SPECULAR_HAS_RTL_TWIN
TEST(TraceWindow, RtlWindowIsTheWholeRunsStretch) { expect_window_is_the_stretch("rtl", false); }
TEST(TraceWindow, RtlSyncWindowIsTheWholeRunsStretch) {
  expect_window_is_the_stretch("rtl-sync", true);
}
#endif

// A window past the last operation is refused before anything runs; one that runs
// past the end is cut at the end.
TEST(TraceWindow, FirstBeyondTheRunIsRefused) {
  const fs::path dir = scratch_dir();
  const Outcome r = run_command(
      "'" + tb + "' --random 10 --vcd '" + (dir / "w.vcd").string() + "' --trace-ops 10:1", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("FIRST = 10 is outside the run's operations [0, 9]"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "w.vcd"));
}

TEST(TraceWindow, WindowPastTheEndEndsWithTheRun) {
  const fs::path dir = scratch_dir();
  const Vcd window = run_vcd(dir, "pin", "tail.vcd", "--trace-ops 38:100");
  EXPECT_EQ(window.rises(var_named(window, "pin35_done")).size(), 2u);
}

}  // namespace
