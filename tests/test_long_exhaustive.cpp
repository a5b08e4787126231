// Issue 2 item 7, proved exhaustively: the Core (bit-accurate, the pin model's twin)
// against the double reference for every n in 1..1000 × every cos code 0..1.0, under
// each normalisation × saturation policy. One process per combination, so ctest can
// run them in parallel. The printed line per combination is the README's accuracy table.
#include <gtest/gtest.h>

#include <iostream>
#include <tuple>

#include "support/accuracy_sweep.h"
#include "support/policies.h"

namespace specular {
namespace {

// Each test covers the operation shard's slice of n: under GoogleTest's sharding, every
// shard process runs it on its own slice (support/operation_shard.h).
SPECULAR_OPERATION_SHARDED_SUITE(Exhaustive);

using testing_support::SweepFigures;

class Exhaustive : public testing_support::PolicyTest {};

TEST_P(Exhaustive, EveryNAndEveryCosCodeMeetsTheBounds) {
  Config config;
  config.normalisation = std::get<0>(GetParam());
  config.saturation = std::get<1>(GetParam());
  const Formats formats(config.widths);
  const auto codes = testing_support::cos_codes(formats, 1);
  ASSERT_EQ(codes.size(), static_cast<std::size_t>(formats.cos.one() + 1));

  const testing_support::OperationShard shard = testing_support::operation_shard();
  const SweepFigures s = testing_support::sweep(config, codes, shard);
  const std::string line = testing_support::summary(config, s);
  std::cout << (shard.whole() ? "" : "shard " + shard.text() + " of n: ") << line << std::endl;
  RecordProperty("accuracy", line);

  EXPECT_EQ(s.evaluations, static_cast<long>(shard.covered(n_min, n_max)) * (formats.cos.one() + 1));
  EXPECT_EQ(s.approx_misses, 0) << s.first_miss;
  EXPECT_EQ(s.norm_misses, 0) << s.first_miss;
  EXPECT_EQ(s.out_misses, 0) << s.first_miss;
  EXPECT_EQ(s.pass1_misses, 0) << s.first_miss;
}

INSTANTIATE_TEST_SUITE_P(Policies, Exhaustive, testing_support::every_policy(),
                         testing_support::policy_name);

}  // namespace
}  // namespace specular
