// The core's constant-folded path (DefaultFormats, docs/performance.md) gives the
// same bits as the same block functions on the run-time Formats, under every policy.
// Sampled here (every 13th cos code, the ends and the codes next to them, every n);
// the one-off exhaustive run over all 65 537 × 1000 inputs is in docs/performance.md.
#include <gtest/gtest.h>

#include "specular/core.h"
#include "support/policies.h"

namespace specular {
namespace {

class CorePaths : public testing_support::PolicyTest {
 protected:
  /// A core of this test's policy pair, on the constant path.
  Core make_core() const {
    Config config;
    config.normalisation = std::get<0>(GetParam());
    config.saturation = std::get<1>(GetParam());
    return Core(config);
  }
};

::testing::AssertionResult same_bits(const Core& core, const Operands& in) {
  const Result fast = core.run(in), generic = core.run_generic(in);
  if (fast.reg9_pass1 == generic.reg9_pass1 && fast.reg9_pass2 == generic.reg9_pass2 &&
      fast.rom38_k == generic.rom38_k && fast.norm39 == generic.norm39 && fast.out == generic.out)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "cos code " << in.cos << ", n " << in.n << ", RGB "
                                       << in.rgb[0] << "," << in.rgb[1] << "," << in.rgb[2]
                                       << ": the paths differ";
}

TEST_P(CorePaths, ConstantPathEqualsRunTimeFormatsPath) {
  const Core core = make_core();
  ASSERT_TRUE(core.uses_default_formats());
  const code_t one = core.formats().cos.one();
  long mismatches = 0;
  Operands in;
  for (code_t c = 0; c <= one; c = (c < 2 || c >= one - 2) ? c + 1 : std::min(c + 13, one - 2)) {
    for (code_t n = 1; n <= 1000; ++n) {
      in.cos = c;
      in.n = n;
      in.rgb = {255, (c + n) & 255, (c * 7 + n) & 255};
      const ::testing::AssertionResult same = same_bits(core, in);
      if (!same && ++mismatches <= 5) ADD_FAILURE() << same.message();
    }
  }
  EXPECT_EQ(mismatches, 0);
}

// The constant path's multipliers skip overflow checks (arith.h): at the ends of every
// input bus — cos codes up to 2^17 − 1 (≈ 2.0), n up to 1023, intensities 0 and 255 —
// they give the bits of the checked run-time path.
TEST_P(CorePaths, BusEndsGiveTheSameBitsOnBothPaths) {
  const Core core = make_core();
  ASSERT_TRUE(core.uses_default_formats());
  for (const code_t c : {0, 1, 2, 32768, 65535, 65536, 65537, 98304, 131071})
    for (const code_t n : {0, 1, 2, 500, 999, 1000, 1001, 1022, 1023})
      for (const code_t i : {0, 1, 128, 254, 255})
        EXPECT_TRUE(same_bits(core, Operands{c, n, {i, 255 - i, 255}}));
}

INSTANTIATE_TEST_SUITE_P(Policies, CorePaths, testing_support::every_policy(),
                         testing_support::policy_name);

TEST(BenchCorePaths, OtherWidthsTakeTheRunTimePath) {
  Config config;
  config.widths.reg9_frac_bits = 24;  // not the default: the constants must not apply
  EXPECT_FALSE(Core(config).uses_default_formats());
  config.widths = Widths{};
  config.widths.rom5_addr_bits = 14;  // same bus formats, another ROM 5 organisation
  EXPECT_FALSE(Core(config).uses_default_formats());
}

}  // namespace
}  // namespace specular
