// The `literal` policy through the pins (spec, Decision "negative results"): the
// second pass's 1 − ½·log2(reg 9) is negative exactly where cos λ < 2^(-3/n); under
// `literal` the pins show those negative values (matching the reference), under
// `clamp` they show 0.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "specular/core.h"
#include "specular/reference.h"
#include "support/pins_run.h"
#include "support/policies.h"

namespace specular {
namespace {

using sc_core::sc_time;

/// cos codes on both sides of the threshold 2^(-3/n) for several n.
std::vector<Operands> around_the_threshold() {
  std::vector<Operands> ops;
  for (unsigned n : {1u, 2u, 5u, 50u, 300u, 1000u}) {
    const double threshold = std::pow(2.0, -3.0 / n);
    for (double f : {0.0, 0.01, 0.3, 0.6, 0.9, 0.98, 0.995, 1.005, 1.02}) {
      const double cos = std::min(1.0, threshold * f);
      Operands op;
      op.cos = static_cast<code_t>(std::llround(std::ldexp(cos, 16)));
      op.n = n;
      op.rgb = {255, 100, 1};
      ops.push_back(op);
    }
  }
  return ops;
}

/// A = 1 − ½·log2(1 − n·log2 cos λ) in double, unclamped: the formula's own sign.
double formula(const Operands& op) {
  const double cos_q = std::max(std::ldexp(static_cast<double>(op.cos), -16), std::ldexp(1.0, -16));
  return 1.0 - 0.5 * std::log2(1.0 - op.n * std::log2(cos_q));
}

class DeviceSaturation : public testing_support::PolicyTest {};

TEST_P(DeviceSaturation, NegativeWhereTheFormulaIsNegativeOnlyUnderLiteral) {
  Config config;
  config.normalisation = std::get<0>(GetParam());
  config.saturation = std::get<1>(GetParam());
  const auto ops = around_the_threshold();
  const auto run = testing_support::run_on_pins(config, sc_time(10, sc_core::SC_NS), ops);
  ASSERT_EQ(run.results.size(), ops.size());
  const Formats f(config.widths);
  const double tolerance = reference::approx_tolerance();
  int negatives = 0;
  for (std::size_t i = 0; i < ops.size(); ++i) {
    const Operands& op = ops[i];
    const Result& r = run.results[i];
    const double a = formula(op);
    const double kn = reference::k(static_cast<unsigned>(op.n), config.normalisation);
    SCOPED_TRACE("n " + std::to_string(op.n) + ", cos code " + std::to_string(op.cos) +
                 ", formula " + std::to_string(a));
    const double approx = f.reg9.to_real(r.reg9_pass2);
    if (config.saturation == Saturation::literal) {
      EXPECT_NEAR(approx, a, tolerance);
      EXPECT_NEAR(f.norm.to_real(r.norm39), kn * a, reference::norm_tolerance(kn));
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(f.out.to_real(r.out[ch]), kn * a * op.rgb[ch],
                    reference::out_tolerance(kn, double(op.rgb[ch]), f.out.lsb()));
      if (a < -tolerance) {  // clearly negative: every stage shows the sign
        ++negatives;
        EXPECT_LT(r.reg9_pass2, 0);
        EXPECT_LT(r.norm39, 0);
        EXPECT_LT(r.out[0], 0);
        EXPECT_LT(r.out[1], 0);
      }
    } else {
      EXPECT_NEAR(approx, std::max(a, 0.0), tolerance);
      EXPECT_GE(r.reg9_pass2, 0);
      EXPECT_GE(r.norm39, 0);
      for (int ch = 0; ch < 3; ++ch) EXPECT_GE(r.out[ch], 0);
      if (a < 0) {
        EXPECT_EQ(r.reg9_pass2, 0);
        EXPECT_EQ(r.out, (std::array<code_t, 3>{0, 0, 0}));
      }
    }
    if (a > tolerance) {
      EXPECT_GT(r.reg9_pass2, 0);
      EXPECT_GT(r.out[0], 0);
    }
  }
  if (config.saturation == Saturation::literal) {
    EXPECT_GE(negatives, 30);
  }
}

INSTANTIATE_TEST_SUITE_P(Policies, DeviceSaturation, testing_support::every_policy(),
                         testing_support::policy_name);

// The deepest negative value: n = 1000, cos λ = 0 gives A = 1 − ½·log2(16 001) ≈ −5.98
// (spec: "A reaches −6.1 at n = 1000, cos λ → 0"; −16 is log2 0 by Decision).
TEST(DeviceLiteral, DeepestNegativeValueFitsEveryBus) {
  Config config;
  config.normalisation = Normalisation::energy;  // the largest K: 159.5
  config.saturation = Saturation::literal;
  Operands op;
  op.cos = 0;
  op.n = 1000;
  op.rgb = {255, 255, 255};
  const auto run = testing_support::run_on_pins(config, sc_time(10, sc_core::SC_NS), {op});
  ASSERT_EQ(run.results.size(), 1u);
  const Formats f(config.widths);
  const double a = 1.0 - 0.5 * std::log2(16001.0);
  const double kn = 1002.0 / (2.0 * M_PI);
  EXPECT_NEAR(f.reg9.to_real(run.results[0].reg9_pass2), a, reference::approx_tolerance());
  EXPECT_NEAR(f.norm.to_real(run.results[0].norm39), kn * a, reference::norm_tolerance(kn));
  EXPECT_NEAR(f.out.to_real(run.results[0].out[0]), kn * a * 255,
              reference::out_tolerance(kn, 255, f.out.lsb()));
  EXPECT_EQ(run.cycles[0], 2.5);
}

}  // namespace
}  // namespace specular
