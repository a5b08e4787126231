// main() for every test executable: GoogleTest runs inside sc_main, as VCML does,
// so that a test may elaborate a design and call sc_start (once per process).
//
// GoogleTest's sharding (GTEST_TOTAL_SHARDS=N, GTEST_SHARD_INDEX=I) is taken over here
// (support/operation_shard.h, plan_gtest_shards): the tests declared operation-sharded
// run in every shard process on the operation shard I/N (SPECULAR_OPERATION_SHARD), every
// other test in exactly one shard process, so the N processes together run exactly the
// unsharded run's operations; GoogleTest's own split of the test list (which would run an
// exhaustive test whole in one process and not at all in the others) is switched off by
// unsetting the two variables before RUN_ALL_TESTS. GTEST_SHARD_STATUS_FILE is left to
// GoogleTest, which touches it as it always does.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <systemc>
#include <utility>
#include <vector>

#include "functional_coverage.h"
#include "operation_shard.h"

int sc_main(int, char**) { return RUN_ALL_TESTS(); }

namespace {

// 0 when the run may go on (sharding applied or not asked for), 1 when refused.
int take_over_gtest_sharding() {
  using namespace specular::testing_support;
  if (GTEST_FLAG_GET(list_tests)) return 0;  // listing ignores sharding, as in GoogleTest
  std::vector<std::pair<std::string, bool>> tests;
  const testing::UnitTest& unit = *testing::UnitTest::GetInstance();
  for (int s = 0; s < unit.total_test_suite_count(); ++s) {
    const testing::TestSuite& suite = *unit.GetTestSuite(s);
    for (int t = 0; t < suite.total_test_count(); ++t) {
      const testing::TestInfo& info = *suite.GetTestInfo(t);
      tests.emplace_back(std::string(info.test_suite_name()) + "." + info.name(),
                         is_operation_sharded(info.test_suite_name()));
    }
  }
  GtestShardPlan plan;
  try {
    plan = plan_gtest_shards(std::getenv("GTEST_TOTAL_SHARDS"), std::getenv("GTEST_SHARD_INDEX"),
                             std::getenv("SPECULAR_OPERATION_SHARD"), tests);
  } catch (const std::invalid_argument& e) {
    std::cerr << "test sharding refused: " << e.what() << '\n';
    return 1;
  }
  if (!plan.active) return 0;
  setenv("SPECULAR_OPERATION_SHARD", plan.operation_shard.c_str(), 1);
  unsetenv("GTEST_TOTAL_SHARDS");
  unsetenv("GTEST_SHARD_INDEX");
  if (!plan.excluded.empty()) {
    std::string filter = GTEST_FLAG_GET(filter);
    if (filter.empty()) filter = "*";
    filter += filter.find('-') == std::string::npos ? "-" : ":";
    for (std::size_t k = 0; k < plan.excluded.size(); ++k) filter += (k ? ":" : "") + plan.excluded[k];
    GTEST_FLAG_SET(filter, filter);
  }
  std::cout << "test sharding: GoogleTest shard " << plan.operation_shard
            << ": operation-sharded tests on operation shard " << plan.operation_shard
            << " of n, " << plan.excluded.size() << " other test(s) left to the other shards\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Every functional coverage bin, for scripts/verify/functional_coverage.py (issue 37).
  if (argc == 2 && std::string(argv[1]) == "--specular-list-functional-bins") {
    for (const auto& bin : specular::testing_support::coverage::all_bins())
      std::cout << bin.name << '\t' << bin.what << '\t' << bin.ignore << '\n';
    return 0;
  }
  // The banner would mix into --gtest_list_tests, which ctest parses.
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  testing::InitGoogleTest(&argc, argv);
  if (take_over_gtest_sharding() != 0) return 1;
  return sc_core::sc_elab_and_sim(argc, argv);
}
