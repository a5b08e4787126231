// specular_bench --quick as a smoke test: it runs every model in its own process,
// exits 0, prints every figure the issue asks for and finds every model bit-exact;
// with two repetitions, every figure as median [min..max] and every target with a
// verdict and a count that agrees with the verdicts (issue 12). The verdict itself is
// a pure function (bench/summary.h), checked here on made-up figures.
// Speed is never asserted (a shared machine may be slow); only presence and exactness.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "specular/variants/variant.h"
#include "support/scratch.h"
#include "summary.h"  // bench/summary.h

namespace {

struct CommandRun {
  int exit_status = -1;
  std::string output;
};

CommandRun run_command(const std::string& command) {
  CommandRun r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) r.output += buffer;
  const int status = ::pclose(pipe);
  r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// The names of the `name: value unit` lines.
std::set<std::string> figure_names(const std::string& output) {
  std::set<std::string> names;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t colon = line.find(": ");
    if (line.empty() || line[0] == '#' || colon == std::string::npos) continue;
    names.insert(line.substr(0, colon));
  }
  return names;
}

const std::string bench = std::string(SPECULAR_BINARY_DIR) + "/bench/specular_bench";

TEST(BenchSmoke, QuickRunPrintsEveryFigureAndIsBitExact) {
  ASSERT_TRUE(std::filesystem::exists(bench)) << bench << " is missing: build target specular_bench";
  const CommandRun r = run_command(bench + " --quick --repetitions 2 --vcd '" +
                                   specular::testing_support::scratch_file("bench_smoke").string() + "' 2>&1");
  EXPECT_EQ(r.exit_status, 0) << r.output;
  const std::set<std::string> names = figure_names(r.output);

  // Every model measured in its own process: results per second and peak memory.
  for (const char* model : {"pow", "core", "pin_vcd_off", "pin_stream", "pin_vcd_on",
                            "pin_vcd_real_views", "tlm_lt_quantum", "tlm_lt", "tlm_pin",
                            "tlm_lt_batch", "tlm_pin_batch", "pin_growth_1k", "pin_growth_10k",
                            "pin_growth_100k", "vcd_growth_10k", "pow_end", "rtl_sync_cpp",
                            "rtl_sync_cpp_stream", "rtl_sync_general_cpp_stream",
                            "rtl_general_cpp_stream", "tlm_lt_quantum_energy", "tlm_lt_batch_energy"}) {
    EXPECT_EQ(names.count(std::string(model) + "_rate"), 1u) << model;
    EXPECT_EQ(names.count(std::string(model) + "_peak_memory"), 1u) << model;
  }
  // Each design variant's C++ model (issue 26), and its ratio to the patent's Core.
  for (const std::string& variant : specular::variants::variant_names())
    for (const char* figure : {"_rate", "_peak_memory", "_vs_core", "_vs_pow"})
      EXPECT_EQ(names.count("variant_" + variant + figure), 1u) << variant << figure;
  // Each one's ratio to std::pow, the VCD's cost, the targets and bit-exactness.
  for (const char* model : {"core", "pin_vcd_off", "pin_stream", "pin_vcd_on", "tlm_lt_quantum", "tlm_lt",
                            "tlm_pin", "tlm_lt_batch", "tlm_pin_batch"})
    EXPECT_EQ(names.count(std::string(model) + "_vs_pow"), 1u) << model;
  for (const char* figure : {"pow_yardstick_rate", "vcd_slowdown", "vcd_real_views_slowdown",
                             "pin_vcd_on_bytes_per_result", "pin_vcd_real_views_bytes_per_result",
                             "vcd_growth_10k_bytes_per_result", "pin_vcd_off_cycles_per_result",
                             "pin_stream_cycles_per_result", "core_default_formats", "target_core_vs_pow",
                             "target_tlm_lt_quantum_vs_pow", "target_pin_vcd_off_vs_pow",
                             "target_pin_stream_vs_pow", "target_vcd_slowdown", "target_tlm_lt_batch_vs_pow",
                             "target_rtl_sync_cpp_stream_vs_pow", "target_rtl_sync_cpp_stream_rate",
                             "target_rtl_sync_vs_pin", "target_rtl_sync_stream_vs_pin_stream",
                             "energy_slowdown_quantum", "energy_slowdown_batch",
                             "target_energy_slowdown_quantum", "target_energy_slowdown_batch",
                             "targets_met", "bit_exact"})
    EXPECT_EQ(names.count(figure), 1u) << figure;

  // Shape: every measured figure is `name: median unit [min..max]` with min <= median <= max,
  // each name once (repetitions are summarised, not listed).
  const std::regex figure_line(R"(^([a-z0-9_]+): ([-0-9.e+]+) (\S+) \[([-0-9.e+]+)\.\.([-0-9.e+]+)\]$)");
  const std::regex target_line(R"(^target_[a-z0-9_]+: (met|not met|within noise) \(.*\)$)");
  std::map<std::string, int> verdicts;
  int figure_lines = 0;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::smatch m;
    if (std::regex_match(line, m, target_line)) {
      ++verdicts[m[1]];
    } else if (std::regex_match(line, m, figure_line)) {
      ++figure_lines;
      const double median = std::stod(m[2]), low = std::stod(m[4]), high = std::stod(m[5]);
      EXPECT_LE(low, median) << line;
      EXPECT_LE(median, high) << line;
    } else {
      // The rest: checksums (hex), bools, and the count of the targets' verdicts.
      EXPECT_TRUE(line.find(" hex") != std::string::npos || line.find(" bool") != std::string::npos ||
                  line.rfind("targets_met: ", 0) == 0)
          << "a line of no known shape: " << line;
    }
  }
  EXPECT_GT(figure_lines, 50);
  // The count is the verdicts' count: "targets_met: M of T (N not met, W within noise)".
  const std::string count = "\ntargets_met: " + std::to_string(verdicts["met"]) + " of 12 (" +
                            std::to_string(verdicts["not met"]) + " not met, " +
                            std::to_string(verdicts["within noise"]) + " within noise)\n";
  EXPECT_EQ(verdicts["met"] + verdicts["not met"] + verdicts["within noise"], 12) << r.output;
  EXPECT_NE(r.output.find(count), std::string::npos) << count << r.output;
  EXPECT_NE(r.output.find("2 interleaved repetitions"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("issue 6"), std::string::npos) << "targets are named by what they measure";
  EXPECT_NE(r.output.find("\nbit_exact: 1 bool\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\ncore_default_formats: 1 bool\n"), std::string::npos) << r.output;
  // The twins' C++ models run their verilations specialised to the default device
  // (issue 28), the *_general_* ones the general verilations.
  EXPECT_NE(r.output.find("\nrtl_sync_cpp_stream_fixed: 1 bool\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nrtl_cpp_stream_fixed: 1 bool\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nrtl_sync_general_cpp_stream_fixed: 0 bool\n"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("FAILED"), std::string::npos) << r.output;
}

TEST(BenchSmoke, RepetitionsOutOfRangeAreRefusedWithTheRange) {
  ASSERT_TRUE(std::filesystem::exists(bench)) << bench << " is missing: build target specular_bench";
  for (const char* bad : {"0", "101", "five", "-3"}) {
    const CommandRun r = run_command(bench + " --repetitions " + bad + " 2>&1");
    EXPECT_EQ(r.exit_status, 2) << bad;
    EXPECT_NE(r.output.find(std::string("--repetitions: ")), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(bad), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("[1, 100]"), std::string::npos) << r.output;
  }
}

// The summary of repetitions: median (mean of the middle two for an even count), min, max.
TEST(BenchSummary, SpreadIsMedianMinAndMax) {
  using specular_bench::spread_of;
  const auto odd = spread_of({5.0, 1.0, 3.0});
  EXPECT_EQ(odd.median, 3.0);
  EXPECT_EQ(odd.min, 1.0);
  EXPECT_EQ(odd.max, 5.0);
  EXPECT_EQ(odd.count, 3u);
  const auto even = spread_of({4.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(even.median, 2.5);
  EXPECT_EQ(even.min, 1.0);
  EXPECT_EQ(even.max, 4.0);
  const auto one = spread_of({0.35});
  EXPECT_EQ(one.median, 0.35);
  EXPECT_EQ(one.min, one.max);
  EXPECT_THROW(spread_of({}), std::invalid_argument);
}

// The verdicts on made-up spreads, both kinds of bound, and the two runs of issue 12.
TEST(BenchSummary, VerdictIsMetNotMetOrWithinNoise) {
  using specular_bench::judge;
  using specular_bench::Spread;
  using specular_bench::Verdict;
  const auto spread = [](double low, double median, double high) { return Spread{median, low, high, 5}; };
  // "at least" (a ratio to std::pow): the whole spread above, below, across the bound.
  EXPECT_EQ(judge(spread(3.2, 3.4, 3.6), true, 3.0), Verdict::met);
  EXPECT_EQ(judge(spread(2.5, 2.7, 2.9), true, 3.0), Verdict::not_met);
  EXPECT_EQ(judge(spread(2.9, 3.2, 3.4), true, 3.0), Verdict::within_noise);
  EXPECT_EQ(judge(spread(2.6, 2.9, 3.1), true, 3.0), Verdict::within_noise) << "a median below is not 'not met'";
  EXPECT_EQ(judge(spread(3.0, 3.0, 3.0), true, 3.0), Verdict::met) << "equal to the bound meets it";
  // "at most" (a slowdown): the mirror image.
  EXPECT_EQ(judge(spread(4.8, 4.9, 5.0), false, 6.0), Verdict::met);
  EXPECT_EQ(judge(spread(6.1, 6.5, 6.8), false, 6.0), Verdict::not_met);
  EXPECT_EQ(judge(spread(6.0, 6.0, 6.0), false, 6.0), Verdict::met);
  // The issue's two runs: VCD slowdown 4.84x and 6.8x against <= 6x, the lt quantum
  // 0.35x and 0.23x against >= 0.25x. Neither run alone could say; together, noise.
  EXPECT_EQ(judge(specular_bench::spread_of({4.84, 6.8}), false, 6.0), Verdict::within_noise);
  EXPECT_EQ(judge(specular_bench::spread_of({0.35, 0.23}), true, 0.25), Verdict::within_noise);
  // A single repetition has no spread: it is met or not met, never noise.
  EXPECT_EQ(judge(specular_bench::spread_of({0.23}), true, 0.25), Verdict::not_met);
  EXPECT_STREQ(to_string(Verdict::within_noise), "within noise");
  EXPECT_STREQ(to_string(Verdict::not_met), "not met");
  EXPECT_STREQ(to_string(Verdict::met), "met");
}

// The count of verdicts the legend's count line prints.
TEST(BenchSummary, VerdictCountAddsUp) {
  specular_bench::VerdictCount count;
  for (const auto v : {specular_bench::Verdict::met, specular_bench::Verdict::met,
                       specular_bench::Verdict::not_met, specular_bench::Verdict::within_noise})
    count.add(v);
  EXPECT_EQ(count.met, 2);
  EXPECT_EQ(count.not_met, 1);
  EXPECT_EQ(count.within_noise, 1);
  EXPECT_EQ(count.total(), 4);
}

TEST(BenchSmoke, UnknownModelIsRefusedWithTheChoices) {
  ASSERT_TRUE(std::filesystem::exists(bench)) << bench << " is missing: build target specular_bench";
  const CommandRun r = run_command(bench + " --model warp_drive 2>&1");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("unknown model warp_drive"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pin_vcd_off"), std::string::npos) << r.output;
}

}  // namespace
