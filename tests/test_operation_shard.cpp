// SPECULAR_OPERATION_SHARD (support/operation_shard.h): the N shards of n partition
// 1..1000 — every n in exactly one shard, so CI's one shard plus the rest is the whole
// exhaustive test — and a malformed value is refused with a message naming it.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "specular/format.h"
#include "support/operation_shard.h"

namespace specular {
namespace testing_support {
namespace {

TEST(OperationShard, UnsetOrEmptyIsTheWholeRun) {
  for (const char* text : {static_cast<const char*>(nullptr), ""}) {
    const OperationShard shard = parse_operation_shard(text);
    EXPECT_TRUE(shard.whole());
    EXPECT_EQ(shard.covered(n_min, n_max), 1000u);
  }
}

TEST(OperationShard, TheShardsPartitionEveryN) {
  for (unsigned count : {1u, 2u, 3u, 4u, 7u, 1000u}) {
    std::vector<unsigned> times(n_max + 1, 0);
    unsigned total = 0;
    for (unsigned index = 0; index < count; ++index) {
      const std::string text = std::to_string(index) + "/" + std::to_string(count);
      const OperationShard shard = parse_operation_shard(text.c_str());
      EXPECT_EQ(shard.text(), text);
      for (unsigned n = n_min; n <= n_max; ++n) times[n] += shard.covers(n) ? 1 : 0;
      total += shard.covered(n_min, n_max);
      // Balanced: ceil or floor of 1000 / N.
      EXPECT_LE(shard.covered(n_min, n_max), (n_max + count - 1) / count) << text;
      EXPECT_GE(shard.covered(n_min, n_max), n_max / count) << text;
    }
    EXPECT_EQ(total, n_max) << "N = " << count;
    for (unsigned n = n_min; n <= n_max; ++n) EXPECT_EQ(times[n], 1u) << "n = " << n << ", N = " << count;
  }
}

TEST(OperationShard, ShardZeroOfFourHoldsTheWorstCaseN) {
  // n = 985 holds the sweep's largest approximation error (README, Accuracy): the shard
  // holding it is (985 - 1) mod 4 = 0.
  EXPECT_TRUE(parse_operation_shard("0/4").covers(985));
  EXPECT_FALSE(parse_operation_shard("1/4").covers(985));
}

TEST(OperationShard, MalformedValuesAreRefusedByName) {
  for (const char* bad : {"4/4", "1/0", "0/1001", "3", "/4", "1/", "-1/4", "a/b", "1/4x", "99999/100000"}) {
    try {
      parse_operation_shard(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("SPECULAR_OPERATION_SHARD = '" + std::string(bad) + "'"), std::string::npos)
          << message;
      EXPECT_NE(message.find("0 <= I < N"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace testing_support
}  // namespace specular
