// specular_bench --quick as a smoke test: it runs every model in its own process,
// exits 0, prints every figure the issue asks for and finds every model bit-exact.
// Speed is never asserted (a shared machine may be slow); only presence and exactness.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>

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
  const CommandRun r = run_command(bench + " --quick --vcd " + testing::TempDir() + "bench_smoke 2>&1");
  EXPECT_EQ(r.exit_status, 0) << r.output;
  const std::set<std::string> names = figure_names(r.output);

  // Every model measured in its own process: results per second and peak memory.
  for (const char* model : {"pow", "core", "pin_vcd_off", "pin_stream", "pin_vcd_on",
                            "pin_vcd_real_views", "tlm_lt_quantum", "tlm_lt", "tlm_pin",
                            "tlm_lt_batch", "tlm_pin_batch", "pin_growth_1k", "pin_growth_10k",
                            "pin_growth_100k", "vcd_growth_10k", "pow_end"}) {
    EXPECT_EQ(names.count(std::string(model) + "_rate"), 1u) << model;
    EXPECT_EQ(names.count(std::string(model) + "_peak_memory"), 1u) << model;
  }
  // Each one's ratio to std::pow, the VCD's cost, the targets and bit-exactness.
  for (const char* model : {"core", "pin_vcd_off", "pin_stream", "pin_vcd_on", "tlm_lt_quantum", "tlm_lt",
                            "tlm_pin", "tlm_lt_batch", "tlm_pin_batch"})
    EXPECT_EQ(names.count(std::string(model) + "_vs_pow"), 1u) << model;
  for (const char* figure : {"pow_yardstick_rate", "vcd_slowdown", "vcd_real_views_slowdown",
                             "pin_vcd_on_bytes_per_result", "pin_vcd_real_views_bytes_per_result",
                             "vcd_growth_10k_bytes_per_result", "pin_vcd_off_cycles_per_result",
                             "pin_stream_cycles_per_result", "core_default_formats", "target_core",
                             "target_tlm_lt_quantum", "target_pin_vcd_off", "target_pin_stream",
                             "target_vcd_slowdown", "target_tlm_lt_batch", "bit_exact"})
    EXPECT_EQ(names.count(figure), 1u) << figure;
  EXPECT_NE(r.output.find("\nbit_exact: 1 bool\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\ncore_default_formats: 1 bool\n"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("FAILED"), std::string::npos) << r.output;
}

TEST(BenchSmoke, UnknownModelIsRefusedWithTheChoices) {
  ASSERT_TRUE(std::filesystem::exists(bench)) << bench << " is missing: build target specular_bench";
  const CommandRun r = run_command(bench + " --model warp_drive 2>&1");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("unknown model warp_drive"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pin_vcd_off"), std::string::npos) << r.output;
}

}  // namespace
