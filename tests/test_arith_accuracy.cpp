// Issue 2 item 7, quick: the same bounds as test_long_exhaustive.cpp on every n in
// 1..1000 but a sample of cos codes (every 97th, plus 0, the smallest codes, the last
// codes below 1.0 and 1.0), so that a quick run still covers every n and every policy.
#include <gtest/gtest.h>

#include <iostream>
#include <tuple>

#include "support/accuracy_sweep.h"
#include "support/policies.h"

namespace specular {
namespace {

class Sampled : public testing_support::PolicyTest {};

TEST_P(Sampled, EveryNAndSampledCosCodesMeetTheBounds) {
  Config config;
  config.normalisation = std::get<0>(GetParam());
  config.saturation = std::get<1>(GetParam());
  const Formats formats(config.widths);
  const auto codes = testing_support::cos_codes(formats, 97);
  ASSERT_GT(codes.size(), 600u);

  const auto s = testing_support::sweep(config, codes);
  const std::string line = testing_support::summary(config, s);
  std::cout << line << std::endl;
  RecordProperty("accuracy", line);

  EXPECT_EQ(s.approx_misses, 0) << s.first_miss;
  EXPECT_EQ(s.norm_misses, 0) << s.first_miss;
  EXPECT_EQ(s.out_misses, 0) << s.first_miss;
  EXPECT_EQ(s.pass1_misses, 0) << s.first_miss;
}

INSTANTIATE_TEST_SUITE_P(Policies, Sampled, testing_support::every_policy(),
                         testing_support::policy_name);

// The near-1 corner the issue warns about: pass 1's error is multiplied by n, so the
// largest n with the last code below 1.0 is where a short log2 path shows first.
TEST(Sampled, LastCodeBelowOneAtLargestNIsWithinBounds) {
  const Core core;
  const Formats& f = core.formats();
  for (unsigned n : {1u, 2u, 999u, 1000u}) {
    Operands in;
    in.cos = f.cos.one() - 1;
    in.n = n;
    const double cos_q = f.cos.to_real(in.cos);
    const Result r = core.run(in);
    const double want = 1.0 - 0.5 * std::log2(1.0 - n * std::log2(cos_q));
    EXPECT_NEAR(f.reg9.to_real(r.reg9_pass2), want, std::ldexp(1.0, -10)) << "n=" << n;
  }
}

}  // namespace
}  // namespace specular
