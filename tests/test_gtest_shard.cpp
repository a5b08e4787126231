// GoogleTest's sharding splits the operations of the exhaustive tests (issue 25):
// with GTEST_TOTAL_SHARDS=N and GTEST_SHARD_INDEX=I (a CI matrix's job I of N),
// support/test_main.cpp runs every operation-sharded test (SPECULAR_OPERATION_SHARDED_SUITE)
// in every shard process on the operation shard I/N of n, and every other test in exactly
// one shard process: the N processes together run what the unsharded run runs. Proved
// here from outside, by running this executable's own disabled fixture tests (which
// record the n and the tests they ran) and a real long test binary under each shard.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "support/operation_shard.h"
#include "support/scratch.h"
#include "support/subprocess.h"

namespace specular {
namespace testing_support {
namespace {

namespace fs = std::filesystem;

// ---- the fixture tests, run only by the tests below in child processes --------------

SPECULAR_OPERATION_SHARDED_SUITE(DISABLED_GtestShardOperations);

void record(const std::string& line) {
  const char* file = std::getenv("SPECULAR_SHARD_RECORD");
  ASSERT_NE(file, nullptr);
  std::ofstream(file, std::ios::app) << line << '\n';
}

TEST(DISABLED_GtestShardOperations, RecordsItsN) {
  const OperationShard shard = operation_shard();
  for (unsigned n = 1; n <= 1000; ++n)
    if (shard.covers(n)) record("n " + std::to_string(n));
}

TEST(DISABLED_GtestShardPlain, A) { record("test A"); }
TEST(DISABLED_GtestShardPlain, B) { record("test B"); }
TEST(DISABLED_GtestShardPlain, C) { record("test C"); }
TEST(DISABLED_GtestShardPlain, D) { record("test D"); }
TEST(DISABLED_GtestShardPlain, E) { record("test E"); }
TEST(DISABLED_GtestShardPlain, F) { record("test F"); }
TEST(DISABLED_GtestShardPlain, G) { record("test G"); }

const std::string self = std::string(SPECULAR_BINARY_DIR) + "/tests/test_gtest_shard";
const std::vector<std::string> plain_tests = {"A", "B", "C", "D", "E", "F", "G"};

struct Recorded {
  std::vector<std::string> lines;
  Outcome outcome;
};

/// This executable's fixture tests in a child, with `env` (assignments) in front;
/// SPECULAR_OPERATION_SHARD and the GoogleTest variables of this process removed first.
Recorded run_fixture(const std::string& env, const std::string& tag) {
  const fs::path dir = scratch_subdir(tag);
  const fs::path file = dir / "record.txt";
  Recorded r;
  r.outcome = run_command("env -u SPECULAR_OPERATION_SHARD -u GTEST_TOTAL_SHARDS -u GTEST_SHARD_INDEX "
                          "SPECULAR_SHARD_RECORD='" + file.string() + "' " + env + " '" + self +
                              "' --gtest_also_run_disabled_tests --gtest_filter='DISABLED_GtestShard*'",
                          dir);
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) r.lines.push_back(line);
  return r;
}

// ---- the plan ----------------------------------------------------------------------

TEST(GtestShard, PlanGivesEveryOtherTestToExactlyOneShardAndEveryShardTheOperationTests) {
  std::vector<std::pair<std::string, bool>> tests;
  for (int k = 0; k < 40; ++k) tests.emplace_back("Suite" + std::to_string(k % 5) + ".Test" + std::to_string(k), k % 4 == 0);
  for (unsigned count : {2u, 3u, 7u}) {
    std::map<std::string, int> runs;
    for (unsigned index = 0; index < count; ++index) {
      const GtestShardPlan plan = plan_gtest_shards(std::to_string(count).c_str(), std::to_string(index).c_str(),
                                                    nullptr, tests);
      EXPECT_TRUE(plan.active);
      EXPECT_EQ(plan.operation_shard, std::to_string(index) + "/" + std::to_string(count));
      const std::set<std::string> excluded(plan.excluded.begin(), plan.excluded.end());
      for (const auto& t : tests) {
        if (t.second) { EXPECT_EQ(excluded.count(t.first), 0u) << t.first << " excluded from shard " << index; }
        if (excluded.count(t.first) == 0) ++runs[t.first];
      }
    }
    for (const auto& t : tests)
      EXPECT_EQ(runs[t.first], t.second ? static_cast<int>(count) : 1) << t.first << ", N = " << count;
  }
}

TEST(GtestShard, UnsetOrOneShardLeavesTheRunAlone) {
  const std::vector<std::pair<std::string, bool>> tests = {{"A.B", false}, {"C.D", true}};
  EXPECT_FALSE(plan_gtest_shards(nullptr, nullptr, "1/4", tests).active);
  const GtestShardPlan one = plan_gtest_shards("1", "0", "1/4", tests);
  EXPECT_FALSE(one.active);
  EXPECT_TRUE(one.excluded.empty());
  // The same split asked twice is no conflict.
  EXPECT_EQ(plan_gtest_shards("4", "1", "1/4", tests).operation_shard, "1/4");
}

TEST(GtestShard, BadOrConflictingVariablesAreRefusedByName) {
  const std::vector<std::pair<std::string, bool>> tests;
  const std::vector<std::pair<const char*, const char*>> bad = {
      {"3", nullptr}, {nullptr, "1"}, {"3", "3"}, {"0", "0"}, {"x", "0"}, {"3", "-1"}, {"1001", "0"}, {"3", ""}};
  for (const auto& b : bad) {
    try {
      plan_gtest_shards(b.first, b.second, nullptr, tests);
      ADD_FAILURE() << "accepted " << (b.first ? b.first : "unset") << " / " << (b.second ? b.second : "unset");
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(std::string("GTEST_TOTAL_SHARDS = '") + (b.first ? b.first : "") + "'"), std::string::npos) << m;
      EXPECT_NE(m.find(std::string("GTEST_SHARD_INDEX = '") + (b.second ? b.second : "") + "'"), std::string::npos) << m;
    }
  }
  try {
    plan_gtest_shards("3", "0", "1/4", tests);
    ADD_FAILURE() << "accepted SPECULAR_OPERATION_SHARD 1/4 under GoogleTest shard 0 of 3";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("SPECULAR_OPERATION_SHARD = '1/4'"), std::string::npos) << m;
    EXPECT_NE(m.find("0/3"), std::string::npos) << m;
  }
}

TEST(GtestShard, ATestNotDeclaredOperationShardedMayNotSplitItsOperations) {
  // This suite is not declared: under GoogleTest's sharding it would run in one process
  // on one slice of n, so operation_shard() refuses it.
  EXPECT_THROW(operation_shard(), std::logic_error);
}

// ---- from outside: shard processes of a real executable -----------------------------

TEST(GtestShard, ThreeShardProcessesTogetherRunExactlyTheUnshardedRun) {
  const Recorded whole = run_fixture("", "whole");
  ASSERT_EQ(whole.outcome.status, 0) << whole.outcome.out << whole.outcome.err;
  std::multiset<std::string> expected;  // computed here: every n, every plain test once
  for (unsigned n = 1; n <= 1000; ++n) expected.insert("n " + std::to_string(n));
  for (const std::string& t : plain_tests) expected.insert("test " + t);
  EXPECT_EQ(std::multiset<std::string>(whole.lines.begin(), whole.lines.end()), expected);

  std::multiset<std::string> together;
  for (unsigned index = 0; index < 3; ++index) {
    const fs::path status = scratch_file("status-" + std::to_string(index));
    const Recorded shard = run_fixture("GTEST_TOTAL_SHARDS=3 GTEST_SHARD_INDEX=" + std::to_string(index) +
                                           " GTEST_SHARD_STATUS_FILE='" + status.string() + "'",
                                       "shard" + std::to_string(index));
    ASSERT_EQ(shard.outcome.status, 0) << shard.outcome.out << shard.outcome.err;
    EXPECT_TRUE(fs::exists(status)) << "GTEST_SHARD_STATUS_FILE not touched by shard " << index;
    EXPECT_NE(shard.outcome.out.find("operation shard " + std::to_string(index) + "/3"), std::string::npos)
        << shard.outcome.out;
    unsigned ns = 0;
    for (const std::string& line : shard.lines) {
      together.insert(line);
      if (line.rfind("n ", 0) == 0) {
        ++ns;
        const unsigned n = static_cast<unsigned>(std::stoul(line.substr(2)));
        EXPECT_EQ((n - 1) % 3, index) << "shard " << index << " ran n = " << n;
      }
    }
    EXPECT_EQ(ns, index == 0 ? 334u : 333u) << "shard " << index;  // its slice, every time
  }
  EXPECT_EQ(together, expected) << "the union of the 3 shards is not the unsharded run";
}

TEST(GtestShard, ConflictingOperationShardIsRefused) {
  const Recorded r = run_fixture("SPECULAR_OPERATION_SHARD=1/4 GTEST_TOTAL_SHARDS=3 GTEST_SHARD_INDEX=0", "conflict");
  EXPECT_EQ(r.outcome.status, 1);
  EXPECT_TRUE(r.lines.empty()) << "tests ran although the sharding was refused";
  EXPECT_NE(r.outcome.err.find("SPECULAR_OPERATION_SHARD = '1/4'"), std::string::npos) << r.outcome.err;
}

TEST(GtestShard, ALongTestBinaryRunsItsSliceInEveryShard) {
  // The exhaustive core tables, one process per shard as ctest runs them (one test each);
  // N = 500: two n per shard. GoogleTest's own split would run each test in shard 0 only.
  const std::string binary = std::string(SPECULAR_BINARY_DIR) + "/tests/test_long_exhaustive";
  ASSERT_TRUE(fs::exists(binary)) << binary << ": build it (cmake --build build --target test_long_exhaustive)";
  for (unsigned index : {0u, 249u, 499u}) {
    const fs::path dir = scratch_subdir("long" + std::to_string(index));
    const Outcome r = run_command("env -u SPECULAR_OPERATION_SHARD GTEST_TOTAL_SHARDS=500 GTEST_SHARD_INDEX=" +
                                      std::to_string(index) + " '" + binary +
                                      "' --gtest_filter='Policies/Exhaustive.*'",
                                  dir);
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    // Every policy's test ran, each on this shard's slice (the test checks its count of
    // operations: 2 n x every cos code).
    const std::string slice = "shard " + std::to_string(index) + "/500 of n: ";
    std::size_t slices = 0;
    for (std::size_t at = r.out.find(slice); at != std::string::npos; at = r.out.find(slice, at + 1)) ++slices;
    EXPECT_EQ(slices, 6u) << r.out;  // 3 normalisations x 2 saturations
    EXPECT_NE(r.out.find("[  PASSED  ] 6 tests."), std::string::npos) << r.out;
  }
}

}  // namespace
}  // namespace testing_support
}  // namespace specular
