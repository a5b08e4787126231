// The study's error tables against values the test computes itself (std::pow, the
// formulas written out here) and against hand-derived facts about each lobe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "error_study.h"
#include "lobes.h"
#include "specular/reference.h"

using namespace specular;
using namespace specular::study;

namespace {

constexpr int cos_bits = 16;
const double lsb = std::ldexp(1.0, -cos_bits);
const double bound = std::ldexp(1.0, -10);  // device against the formula (issue 2)
constexpr double degrees_per_radian = 57.29577951308232;

// One evaluator for the whole file: building it fills two ROM 5 tables.
const LobeEvaluator& evaluator() {
  static const LobeEvaluator e;
  return e;
}

}  // namespace

TEST(StudyErrors, SchlickAndUs5739820ErrorsAtChosenPoints) {
  const LobeTables t = evaluator().tables(10);
  for (code_t code : {0, 16384, 32768, 52429, 60000, 65000, 65535, 65536}) {
    const double c = code * lsb;
    const double exact = std::pow(c, 10.0);
    const double schlick_inline = c / (10.0 - 10.0 * c + c);
    const double base = std::max(0.0, 1.0 - 10.0 * (1.0 - c) / 4.0);
    const double us_inline = base * base * base * base;
    const auto i = static_cast<std::size_t>(code);
    EXPECT_DOUBLE_EQ(t.cos[i], c);
    EXPECT_NEAR(t.exact[i], exact, 1e-15);
    EXPECT_NEAR(t.of(Method::schlick)[i] - t.exact[i], schlick_inline - exact, 1e-15) << c;
    EXPECT_NEAR(t.of(Method::us5739820)[i] - t.exact[i], us_inline - exact, 1e-15) << c;
  }
  // Hand values: at cos = 0.5, n = 10, Schlick = 0.5/5.5 = 1/11 and cos^10 = 1/1024.
  EXPECT_NEAR(t.of(Method::schlick)[32768] - t.exact[32768], 1.0 / 11 - 1.0 / 1024, 1e-15);
  // US 5739820 is zero for cos ≤ 1 − 4/n = 0.6.
  EXPECT_EQ(t.of(Method::us5739820)[32768], 0.0);
}

TEST(StudyErrors, KnownMaximaOfEachMethod) {
  // Schlick at n = 1 is t itself; US 5739820 at n = 4 is t⁴ — both exact.
  {
    const LobeTables t = evaluator().tables(1);
    EXPECT_LT(max_abs_difference(t.of(Method::schlick), t.exact, t.cos).value, 1e-15);
    // US 5739820 at n = 1: (1 − (1 − t)/4)⁴ − t is largest at t = 0: (3/4)⁴.
    const MaxError us = max_abs_difference(t.of(Method::us5739820), t.exact, t.cos);
    EXPECT_NEAR(us.value, 81.0 / 256.0, 1e-15);
    EXPECT_EQ(us.at_cos, 0.0);
    // The clamped formula's worst error is at x = n·log2 t = −3 (t = 1/8, a code):
    // 0 − 1/8. The device is within the bound of it.
    const MaxError formula = max_abs_difference(t.of(Method::formula_clamp), t.exact, t.cos);
    EXPECT_NEAR(formula.value, 0.125, 1e-12);
    EXPECT_DOUBLE_EQ(formula.at_cos, 0.125);
    EXPECT_NEAR(max_abs_difference(t.of(Method::device_clamp), t.exact, t.cos).value, 0.125,
                bound);
  }
  {
    const LobeTables t = evaluator().tables(4);
    EXPECT_LT(max_abs_difference(t.of(Method::us5739820), t.exact, t.cos).value, 1e-15);
  }
  // Large n: Schlick's error tends to max over y of |1/(1 + y) − e^-y| ≈ 0.2036 (y = n(1 − t)),
  // computed here on a fine grid.
  double limit = 0;
  for (int i = 0; i <= 200000; ++i) {
    const double y = i * 1e-4;
    limit = std::max(limit, std::abs(1.0 / (1.0 + y) - std::exp(-y)));
  }
  const LobeTables t = evaluator().tables(1000);
  EXPECT_NEAR(max_abs_difference(t.of(Method::schlick), t.exact, t.cos).value, limit, 0.002);
}

TEST(StudyErrors, FormulaTurnsNegativeBelowTwoToTheMinusThreeOverN) {
  // 1 − ½·log2(1 − n·log2 t) < 0  ⇔  1 − n·log2 t > 4  ⇔  n·log2 t < −3  ⇔  t < 2^(−3/n).
  for (unsigned n : {1u, 2u, 5u, 10u, 50u, 100u, 500u, 1000u}) {
    const double t0 = std::exp2(-3.0 / n);
    EXPECT_DOUBLE_EQ(formula_zero_crossing(n), t0);
    const auto formula = [n](double t) { return 1.0 - 0.5 * std::log2(1.0 - n * std::log2(t)); };
    EXPECT_GT(formula(t0 * (1 + 1e-9)), 0.0) << "n = " << n;
    EXPECT_LT(formula(t0 * (1 - 1e-9)), 0.0) << "n = " << n;
  }
  // The same point in degrees, for docs/study.md: n = 1 → 82.82°, n = 1000 → 3.69°.
  EXPECT_NEAR(std::acos(formula_zero_crossing(1)) * degrees_per_radian, 82.82, 0.01);
  EXPECT_NEAR(std::acos(formula_zero_crossing(1000)) * degrees_per_radian, 3.69, 0.01);
}

TEST(StudyErrors, DeviceZeroCrossingIsNearTheFormulas) {
  // Near t0 = 2^(−3/n), dA/dt = 1/(2·ln 2·(1 − x)) · n/(t·ln 2) with x = −3: about
  // 0.26·n/t0. A device error of at most 2^-10 moves the crossing by at most
  // 2^-10 · t0 / (0.26·n), plus one code for the rounding of the crossing to a code.
  for (unsigned n : {1u, 10u, 100u, 1000u}) {
    const double t0 = std::exp2(-3.0 / n);
    const double slope = n / (2 * std::log(2.0) * 4 * t0 * std::log(2.0));
    const double crossing = device_zero_crossing(evaluator().tables(n));
    EXPECT_NEAR(crossing, t0, bound / slope + lsb) << "n = " << n;
  }
}

TEST(StudyErrors, DeviceStaysWithinTheBoundOfTheFormulaInBothPolicies) {
  for (unsigned n : {1u, 2u, 50u, 985u, 1000u}) {
    const LobeTables t = evaluator().tables(n);
    for (std::size_t c = 0; c < t.cos.size(); ++c) {
      const double formula = 1.0 - 0.5 * std::log2(1.0 - n * std::log2(std::max(t.cos[c], lsb)));
      ASSERT_NEAR(t.of(Method::device_literal)[c], formula, bound) << "n = " << n << ", code " << c;
      ASSERT_NEAR(t.of(Method::device_clamp)[c], std::max(0.0, formula), bound)
          << "n = " << n << ", code " << c;
    }
  }
}
