// The soak (issue 5, item 4) at a reduced count: specular_soak as a subprocess, every
// stage with zero mismatches against the reference and the core, and resident memory
// that does not grow between early and late in each stage. A run with an injected
// fault shows that the scoreboard does count mismatches.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/soak_run.h"

namespace fs = std::filesystem;

namespace {

using specular::testing_support::run_soak;
using specular::testing_support::soak;
using specular::testing_support::SoakRun;

const std::map<std::string, double> planned = {
    {"core", 1000000}, {"pin", 200000}, {"tlm", 200000}, {"tlm-pin", 20000}};
const std::string counts = "--core 1000000 --pin 200000 --tlm 200000 --tlm-pin 20000";

TEST(LongSoak, EveryStageMatchesTheReferenceAndTheCoreWithFlatMemory) {
  ASSERT_TRUE(fs::exists(soak)) << soak;
  const SoakRun r = run_soak(counts + " --seed 7");
  EXPECT_EQ(r.status, 0) << r.out;
  ASSERT_EQ(r.stages.size(), planned.size()) << r.out;
  for (const auto& [stage, ops] : planned) {
    SCOPED_TRACE(stage);
    const auto& f = r.stages.at(stage);
    EXPECT_EQ(f.at("ops"), ops);
    EXPECT_EQ(f.at("mismatches"), 0);
    EXPECT_EQ(f.at("reference_failures"), 0);
    EXPECT_EQ(f.at("bit_mismatches"), 0);
    EXPECT_GT(f.at("rss_early_kib"), 0) << "VmRSS read from /proc/self/status";
    // Flat: a stage streams in fixed-size chunks, so its resident memory after a tenth
    // of the run and at the end differ by little; 16 MiB is a generous margin (a leak
    // of even 16 bytes per operation would exceed it over the core stage).
    EXPECT_LE(f.at("rss_late_kib") - f.at("rss_early_kib"), 16 * 1024);
  }
}

TEST(LongSoak, AnInjectedFaultIsCountedInEveryStage) {
  const SoakRun r = run_soak("--core 5000 --pin 5000 --tlm 5000 --tlm-pin 500 --inject-fault 321");
  EXPECT_EQ(r.status, 1) << r.out;
  ASSERT_EQ(r.stages.size(), 4u) << r.out;
  for (const auto& [stage, f] : r.stages) {
    SCOPED_TRACE(stage);
    EXPECT_EQ(f.at("mismatches"), 1);
    EXPECT_EQ(f.at("reference_failures"), 1) << "1024 units of R is outside every tolerance";
    EXPECT_EQ(f.at("bit_mismatches"), stage == "core" ? 0 : 1);
  }
}

TEST(LongSoak, BadOptionsAreRefused) {
  for (const char* arguments : {"--core -1", "--pin many", "--frobnicate 3", "--seed"}) {
    const SoakRun r = run_soak(std::string(arguments) + " 2>/dev/null");
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_TRUE(r.stages.empty()) << arguments;
  }
}

}  // namespace
