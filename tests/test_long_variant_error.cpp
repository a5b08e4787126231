// specular_variant_error's whole run (issue 26): every cos code × every n. The patent's
// device must show docs/accuracy.md's figures where the measures coincide: its largest
// miss of K(n)·cos^n is 2π/3 · 1/8 at n = 1, cos = 1/8 (A clamped to 0 there), and
// its largest |out − out_ref| at R = 255 is 0.0111. Every registered variant runs every
// operation of its operation shard and gives finite figures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "shard.h"
#include "specular/variants/variant.h"
#include "support/operation_shard.h"
#include "variant_error.h"

using namespace specular;
using namespace specular::tb;

TEST(VariantErrorWhole, PatentAgreesWithDocsAccuracy) {
  const VariantError e = measure_variant_error("patent", ErrorSweepRange{});
  EXPECT_EQ(e.operations, 65537000u);
  EXPECT_NEAR(e.lobe.max_abs, 2 * std::acos(-1.0) / 3 * 0.125, 1e-5);
  EXPECT_EQ(e.lobe.max_cos_code, 8192);
  EXPECT_EQ(e.lobe.max_n, 1u);
  ASSERT_TRUE(e.has_formula);
  EXPECT_NEAR(e.formula_out.max_abs, 0.0111, 0.00005);  // docs/accuracy.md: 0.0111 (7.3 %)
  EXPECT_LE(e.formula_lobe.max_abs, std::ldexp(1.0, -10) * 2 * std::acos(-1.0) / 3);  // issue 2's bound at K(1)
}

// Every variant on this process's slice of n (support/operation_shard.h: CI runs one
// shard, `scripts/test.sh --full` all of them), every cos code: the N shards together
// run every operation. Its own suite, so that the patent's whole run above is not split.
SPECULAR_OPERATION_SHARDED_SUITE(VariantErrorEveryVariant);

TEST(VariantErrorEveryVariant, RunsEveryOperationOfItsShard) {
  const testing_support::OperationShard shard = testing_support::operation_shard();
  ErrorSweepRange range;
  range.shard = Shard{shard.index, shard.count};
  const std::uint64_t expected = 65537ull * shard.covered(1, 1000);  // every cos code of U1.16
  for (const std::string& name : variants::variant_names()) {
    const VariantError e = measure_variant_error(name, range);
    EXPECT_EQ(e.operations, expected) << name << ", shard " << shard.text();
    EXPECT_TRUE(std::isfinite(e.lobe.max_abs) && std::isfinite(e.lobe.mean_abs())) << name;
    EXPECT_TRUE(std::isfinite(e.out.max_abs) && std::isfinite(e.out.mean_abs())) << name;
    EXPECT_GE(e.lobe.max_n, 1u) << name;
    EXPECT_TRUE(shard.covers(e.lobe.max_n)) << name << ": largest miss at n = " << e.lobe.max_n
                                            << ", outside shard " << shard.text();
    std::printf("%s (shard %s): lobe max %.6g at (%lld, %u), mean %.6g; out max %.6g at (%lld, %u), mean %.6g; %.1f s\n",
                name.c_str(), shard.text().c_str(), e.lobe.max_abs, e.lobe.max_cos_code, e.lobe.max_n,
                e.lobe.mean_abs(), e.out.max_abs, e.out.max_cos_code, e.out.max_n, e.out.mean_abs(), e.seconds);
  }
}
