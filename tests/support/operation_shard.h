// The exhaustive tests' operations split into shards by n (issue 31): with
// SPECULAR_OPERATION_SHARD=I/N in the environment, a long test covers only the n in
// 1..1000 with (n − 1) mod N = I — still every device, every cos code and every policy
// it covers whole, on a 1/N slice of n — and the N shards together are the whole test.
// CI runs one shard of every long test (scripts/test.sh, I from the commit); the whole
// of each runs with `scripts/test.sh --full` (docs/testing.md). Unset: the whole test.
//
// GoogleTest's sharding (GTEST_TOTAL_SHARDS, GTEST_SHARD_INDEX; a CI matrix's job I of
// N) splits the operations too: tests/support/test_main.cpp turns it into the operation
// shard I/N for the tests declared operation-sharded (SPECULAR_OPERATION_SHARDED_SUITE,
// which run in every shard process on their slice of n) and gives every other test to
// exactly one shard process (plan_gtest_shards below), so the N processes together run
// exactly what the unsharded run runs. docs/testing/isolation.md, "Sharding under GoogleTest".
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace specular {
namespace testing_support {

struct OperationShard {
  unsigned index = 0;  ///< I, 0 ≤ I < N
  unsigned count = 1;  ///< N, 1 ≤ N ≤ max_count

  static constexpr unsigned max_count = 1000;  ///< one n per shard at most

  /// Whether operations of exponent `n` (≥ 1) belong to this shard.
  bool covers(unsigned n) const { return (n - 1) % count == index; }

  /// How many n in first..last (first ≥ 1) this shard covers.
  unsigned covered(unsigned first, unsigned last) const {
    unsigned k = 0;
    for (unsigned n = first; n <= last; ++n) k += covers(n) ? 1u : 0u;
    return k;
  }

  bool whole() const { return count == 1; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// Parses "I/N"; an empty or missing text is the whole run. Anything else is refused
/// with a message naming the value and the allowed form.
inline OperationShard parse_operation_shard(const char* text) {
  OperationShard shard;
  if (text == nullptr || *text == '\0') return shard;
  const std::string value(text);
  const auto refuse = [&value]() {
    return std::invalid_argument("SPECULAR_OPERATION_SHARD = '" + value +
                                 "': expected I/N, integers with 0 <= I < N and 1 <= N <= " +
                                 std::to_string(OperationShard::max_count));
  };
  const std::size_t slash = value.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == value.size()) throw refuse();
  const auto number = [&](const std::string& digits) {
    if (digits.size() > 4 || digits.find_first_not_of("0123456789") != std::string::npos)
      throw refuse();
    return static_cast<unsigned>(std::stoul(digits));
  };
  shard.index = number(value.substr(0, slash));
  shard.count = number(value.substr(slash + 1));
  if (shard.count < 1 || shard.count > OperationShard::max_count || shard.index >= shard.count)
    throw refuse();
  return shard;
}

/// The test suites whose tests split their operations by operation_shard(): the base
/// names (a TEST_P suite "Policies/Exhaustive" is registered as "Exhaustive").
inline std::set<std::string>& operation_sharded_suites() {
  static std::set<std::string> suites;
  return suites;
}

struct OperationShardedSuite {
  explicit OperationShardedSuite(const char* suite) { operation_sharded_suites().insert(suite); }
};

/// Declares, at namespace scope of a test file, that every test of `Suite` covers only
/// operation_shard()'s slice of n: under GoogleTest's sharding it runs in every shard
/// process (each on its own slice) instead of in one.
#define SPECULAR_OPERATION_SHARDED_SUITE(Suite)                                             \
  static const ::specular::testing_support::OperationShardedSuite specular_operation_sharded_##Suite( \
      #Suite)

/// Whether a test suite (as GoogleTest names it: "Prefix/Suite" for TEST_P) is declared
/// operation-sharded.
inline bool is_operation_sharded(const std::string& suite_name) {
  const std::size_t slash = suite_name.rfind('/');
  const std::string base = slash == std::string::npos ? suite_name : suite_name.substr(slash + 1);
  return operation_sharded_suites().count(base) != 0;
}

/// What GoogleTest's sharding variables make of this process (test_main.cpp applies it).
struct GtestShardPlan {
  bool active = false;                ///< GTEST_TOTAL_SHARDS > 1
  std::string operation_shard;        ///< "I/N" for SPECULAR_OPERATION_SHARD when active
  std::vector<std::string> excluded;  ///< "Suite.Name" of the tests other shards run
};

/// The shard process a test that is not operation-sharded runs in: FNV-1a of its full
/// name mod N, the same in every process whatever the filter (under ctest each process
/// runs one test, so a position in the list, gtest's own rule, would put every test on
/// shard 0).
inline unsigned test_list_shard(const std::string& full_name, unsigned count) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : full_name) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return static_cast<unsigned>(h % count);
}

/// GTEST_TOTAL_SHARDS = `total`, GTEST_SHARD_INDEX = `index` (nullptr: unset) over the
/// registered tests (full name, operation-sharded?). Unset or N = 1: inactive. Refused,
/// as GoogleTest refuses them, with a message naming the values: one variable without
/// the other, a value that is not an integer, I outside 0..N-1; and N above
/// OperationShard::max_count, or a SPECULAR_OPERATION_SHARD (`operation_env`) other
/// than I/N (two splits of n at once would run neither).
inline GtestShardPlan plan_gtest_shards(const char* total, const char* index, const char* operation_env,
                                        const std::vector<std::pair<std::string, bool>>& tests) {
  GtestShardPlan plan;
  const bool has_total = total != nullptr && *total != '\0';
  const bool has_index = index != nullptr && *index != '\0';
  if (!has_total && !has_index) return plan;
  const std::string shown = std::string("GTEST_TOTAL_SHARDS = '") + (has_total ? total : "") +
                            "', GTEST_SHARD_INDEX = '" + (has_index ? index : "") + "'";
  if (!has_total || !has_index)
    throw std::invalid_argument(shown + ": set both or neither");
  const auto number = [&shown](const std::string& digits) {
    if (digits.empty() || digits.size() > 4 || digits.find_first_not_of("0123456789") != std::string::npos)
      throw std::invalid_argument(shown + ": expected integers with 0 <= index < total and 1 <= total <= " +
                                  std::to_string(OperationShard::max_count));
    return static_cast<unsigned>(std::stoul(digits));
  };
  const unsigned n = number(total), i = number(index);
  if (n < 1 || n > OperationShard::max_count || i >= n)
    throw std::invalid_argument(shown + ": expected integers with 0 <= index < total and 1 <= total <= " +
                                std::to_string(OperationShard::max_count));
  if (n == 1) return plan;
  plan.active = true;
  plan.operation_shard = std::to_string(i) + "/" + std::to_string(n);
  if (operation_env != nullptr && *operation_env != '\0' && plan.operation_shard != operation_env)
    throw std::invalid_argument(shown + " make the operation shard " + plan.operation_shard +
                                ", but SPECULAR_OPERATION_SHARD = '" + operation_env +
                                "' asks for another: unset one of them");
  for (const auto& test : tests)
    if (!test.second && test_list_shard(test.first, n) != i) plan.excluded.push_back(test.first);
  return plan;
}

/// The shard this test process runs (SPECULAR_OPERATION_SHARD; under GoogleTest's
/// sharding test_main.cpp sets it to I/N). A test calling it must be declared with
/// SPECULAR_OPERATION_SHARDED_SUITE, or GoogleTest's sharding would run it in one
/// process on one slice: refused (std::logic_error) when a test is running.
inline OperationShard operation_shard() {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  if (test != nullptr && !is_operation_sharded(test->test_suite_name()))
    throw std::logic_error(std::string("test ") + test->test_suite_name() + "." + test->name() +
                           " splits its operations (operation_shard()) but its suite is not declared "
                           "with SPECULAR_OPERATION_SHARDED_SUITE (tests/support/operation_shard.h)");
  return parse_operation_shard(std::getenv("SPECULAR_OPERATION_SHARD"));
}

}  // namespace testing_support
}  // namespace specular
