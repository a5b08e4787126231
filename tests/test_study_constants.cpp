// The minimax search for the constants on pins 19 and 20 (issue 14): its error
// function against a dense grid in x, and its answers against exhaustive scans.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "constants_search.h"

using namespace specular::study;

namespace {
constexpr double ln2 = 0.693147180559945309417232121458176568;

/// max |s·max(0, a − h·log2(a + x)) − 2^−x| on a dense grid of x: no root finding.
double dense_error(double a, double h) {
  const double s = 1.0 / (a - h * std::log2(a));
  double worst = 0;
  for (double x = 0; x <= 60; x += 1e-5)
    worst = std::max(worst, std::abs(s * std::max(0.0, a - h * std::log2(a + x)) - std::exp2(-x)));
  return worst;
}

double a_of(std::int64_t code) { return std::ldexp(static_cast<double>(code), -search_a_frac_bits); }
}  // namespace

TEST(ConstantsError, PatentConstantsPeakAtThreeWithOneEighth) {
  // a = 1, h = ½: zero crossing at x = 3, where cos^n = 2^−3 (spec §1: 0.125).
  const ConstantsError e = constants_error(1.0, 0.5);
  EXPECT_DOUBLE_EQ(e.below, 0.125);
  EXPECT_LT(e.above, 0.01);
}

TEST(ConstantsError, AgreesWithADenseGrid) {
  const double points[][2] = {{1.0, 0.5}, {1.148987293, 0.5}, {0.373026371, 0.16015625},
                              {0.3, 0.2}, {2.0, 1.0}, {0.9, 0.6}, {5.0, 0.1}};
  for (const auto& p : points) {
    SCOPED_TRACE(::testing::Message() << "a = " << p[0] << ", h = " << p[1]);
    // A grid only samples: it never exceeds the exact maximum, and it misses a smooth
    // extremum by (step/2)²·|e''|/2 and the zero crossing's kink by step × slope (< 2).
    const double exact = constants_error(p[0], p[1]).worst(), grid = dense_error(p[0], p[1]);
    EXPECT_LE(grid, exact + 1e-12);
    EXPECT_LE(exact, grid + 2e-5);
  }
}

TEST(ConstantsSearch, HalfBeatsEveryCodeOfAnExhaustiveScan) {
  const ConstantsResult r = search_constants(1, 1);  // h = ½
  EXPECT_EQ(r.h, 0.5);
  EXPECT_LT(r.error.worst(), 0.075);  // the issue's bound for minimax-half
  // Every code within ±2^16 of the answer, and every 2^10-th code across [h/ln2, 2.5].
  for (std::int64_t a = r.a_code - (1 << 16); a <= r.a_code + (1 << 16); ++a)
    ASSERT_GE(constants_error(a_of(a), 0.5).worst(), r.error.worst()) << "a code " << a;
  const auto lo = static_cast<std::int64_t>(std::ceil(std::ldexp(0.5 / ln2, search_a_frac_bits)));
  for (std::int64_t a = lo; a <= std::int64_t{10} << 20; a += 1 << 10)
    ASSERT_GE(constants_error(a_of(a), 0.5).worst(), r.error.worst()) << "a code " << a;
}

TEST(ConstantsSearch, FreeHOnThreeBitsBeatsEveryPointOfAScan) {
  const ConstantsResult r = search_constants(3);
  for (std::int64_t hc = 1; hc <= 15; ++hc) {
    const double h = std::ldexp(static_cast<double>(hc), -3);
    const auto lo = static_cast<std::int64_t>(std::ceil(std::ldexp(h / ln2, search_a_frac_bits)));
    for (std::int64_t a = lo; a <= std::int64_t{12} << 20; a += 1 << 11)
      ASSERT_GE(constants_error(a_of(a), h).worst(), r.error.worst()) << "h " << h << " a " << a_of(a);
  }
  // ... and no neighbour on the grid does better.
  for (std::int64_t dh = -1; dh <= 1; ++dh)
    for (std::int64_t da = -4096; da <= 4096; ++da) {
      const double h = std::ldexp(static_cast<double>(r.h_code + dh), -3);
      if (a_of(r.a_code + da) < h / ln2) continue;
      ASSERT_GE(constants_error(a_of(r.a_code + da), h).worst(), r.error.worst());
    }
}

TEST(ConstantsSearch, MoreBitsNeverWorseAndTheIssuesBoundsHold) {
  double previous = 1;
  for (int f = 1; f <= 12; ++f) {
    const ConstantsResult r = search_constants(f);
    EXPECT_LE(r.error.worst(), previous) << "F = " << f;  // a finer grid holds the coarser one
    previous = r.error.worst();
    // The optimum balances the two errors (minimax equioscillation).
    EXPECT_NEAR(r.error.above, r.error.below, 1e-5) << "F = " << f;
    EXPECT_NEAR(r.s * (r.a - r.h * std::log2(r.a)), 1.0, 1e-15);
  }
  EXPECT_LT(previous, 0.042);
}

TEST(ConstantsSearch, RefusesAnOutOfRangeGrid) {
  EXPECT_THROW(search_constants(0), std::invalid_argument);
  EXPECT_THROW(search_constants(25), std::invalid_argument);
  EXPECT_THROW(search_constants(1, 4), std::invalid_argument);
}
