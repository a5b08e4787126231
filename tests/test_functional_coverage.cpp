// The functional coverage bins and their recorder (issue 37, support/functional_coverage.h):
// the classifiers put hand-picked values in the bins the issue names, every bin is declared
// once, an undeclared bin is refused by name, and a process run with
// SPECULAR_FUNCTIONAL_COVERAGE writes exactly its hits, while one without writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/functional_coverage.h"
#include "support/scratch.h"
#include "support/subprocess.h"

namespace {

using namespace specular;
using namespace specular::testing_support;
using V = std::vector<std::string>;

TEST(FunctionalCoverage, ClassifiersPutHandPickedValuesInTheirBins) {
  EXPECT_EQ(coverage::cos_bins(0, 16), V({"cos/zero"}));
  EXPECT_EQ(coverage::cos_bins(1, 16), V({"cos/one_lsb", "cos/rom5_segment_0"}));
  EXPECT_EQ(coverage::cos_bins(3, 16), V({"cos/rom5_segment_1"}));
  EXPECT_EQ(coverage::cos_bins(32768, 16), V({"cos/rom5_segment_15"}));
  EXPECT_EQ(coverage::cos_bins(65535, 16), V({"cos/rom5_segment_15"}));
  EXPECT_EQ(coverage::cos_bins(65536, 16), V({"cos/max", "cos/rom5_segment_16"}));
  EXPECT_EQ(coverage::n_bins(1), V({"n/1"}));
  EXPECT_EQ(coverage::n_bins(2), V({"n/2"}));
  EXPECT_EQ(coverage::n_bins(3), V({"n/other"}));
  EXPECT_EQ(coverage::n_bins(4), V({"n/power_of_two"}));
  EXPECT_EQ(coverage::n_bins(512), V({"n/power_of_two"}));
  EXPECT_EQ(coverage::n_bins(1000), V({"n/1000"}));
  EXPECT_EQ(coverage::n_bins(1001), V({}));
  EXPECT_EQ(coverage::rgb_bins(0), V({"rgb/0"}));
  EXPECT_EQ(coverage::rgb_bins(1), V({"rgb/1"}));
  EXPECT_EQ(coverage::rgb_bins(255), V({"rgb/255"}));
  EXPECT_EQ(coverage::rgb_bins(128), V({}));
  EXPECT_EQ(coverage::width_class(2), "2");
  EXPECT_EQ(coverage::width_class(8), "8");
  EXPECT_EQ(coverage::width_class(12), "burst");
}

TEST(FunctionalCoverage, EveryBinIsDeclaredOnceAndTheCrossesAreWhole) {
  std::set<std::string> names;
  std::size_t policies = 0, accesses = 0, ignored_policies = 0;
  for (const auto& bin : coverage::all_bins()) {
    EXPECT_TRUE(names.insert(bin.name).second) << "declared twice: " << bin.name;
    if (bin.name.rfind("policy/", 0) == 0) {
      ++policies;
      ignored_policies += !bin.ignore.empty();
    }
    accesses += bin.name.rfind("access/", 0) == 0;
  }
  EXPECT_EQ(policies, 4u * 2u * 3u);  // normalisation x saturation x constants
  EXPECT_EQ(ignored_policies, 1u);    // device-energy x literal x patent is refused
  // every register x read/write x 5 widths x legal/illegal x b/nb/dbg, and unmapped offsets
  EXPECT_EQ(accesses, register_count * 2 * 5 * 2 * 3 + 2 * 3);
  EXPECT_TRUE(names.count("cos/rom5_segment_16") && names.count("reset/during_operation") &&
              names.count("interrupt/masked/acknowledged_after_next_start"));
}

// Run as a child process (below), with or without SPECULAR_FUNCTIONAL_COVERAGE.
TEST(FunctionalCoverage, DISABLED_RecordsThreeHits) {
  coverage::hit("cos/zero");
  coverage::hit("cos/zero");
  Config config;
  config.saturation = Saturation::literal;
  coverage::record_policy(config);
  if (coverage::enabled()) {
    EXPECT_THROW(coverage::hit("cos/no_such_bin"), std::logic_error);
  }
}

TEST(FunctionalCoverage, AProcessWritesExactlyItsHitsAndNothingWhenOff) {
  const std::filesystem::path on = scratch_subdir("on"), log = scratch_subdir("log");
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::string run = "'" + self + "' --gtest_also_run_disabled_tests "
                          "--gtest_filter=FunctionalCoverage.DISABLED_RecordsThreeHits";
  const Outcome with = run_command("SPECULAR_FUNCTIONAL_COVERAGE='" + on.string() + "' " + run, log, "on");
  ASSERT_EQ(with.status, 0) << with.out << with.err;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(on)) files.push_back(entry.path());
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].filename().string().rfind("fcov-", 0), 0u);
  EXPECT_EQ(slurp(files[0]), "cos/zero\t2\npolicy/patent/literal/patent\t1\n");
  const std::filesystem::path off = scratch_subdir("off");
  const Outcome without = run_command("cd '" + off.string() + "' && env -u SPECULAR_FUNCTIONAL_COVERAGE " + run,
                                      log, "off");
  ASSERT_EQ(without.status, 0) << without.out << without.err;
  EXPECT_TRUE(std::filesystem::is_empty(off));
}

}  // namespace
