// Variant us5739820 (docs/variants/us5739820.md) against double references computed
// here: the exact lobe K(n)·cos^n (reference.h) and US 5,739,820's formula
// (1 − (1 − cos)·n/2^k)^(2^k) written again in double. The variant's error is the
// formula's (up to 0.0352 at n = 3) plus its arithmetic's, bounded below bit by bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "specular/reference.h"
#include "specular/variants/us5739820.h"
#include "specular/variants/variant.h"

namespace specular {
namespace {

using variants::make_variant;

constexpr long cos_one = 1L << 16;

/// k = round(log2 n), from the logarithm in double (log2 n is never exactly k + ½).
int k_of(long n) { return static_cast<int>(std::lround(std::log2(static_cast<double>(n)))); }

/// The patent's formula in double: max(0, 1 − x·n/2^k)^(2^k), x = 1 − cos.
double formula(double cos_q, long n) {
  const int k = k_of(n);
  const double base = std::max(0.0, 1.0 - (1.0 - cos_q) * n / std::ldexp(1.0, k));
  return std::pow(base, std::ldexp(1.0, k));
}

/// What the fixed-point arithmetic may add to K·formula, on the lobe (S10.20):
///   k squarings rounded on U1.30, each ≤ 2^−31, amplified by the later squarings
///   (d y^(2^m)/dy ≤ 2^m on [0, 1]): < 2^(k−31); rounding to S14.22: ≤ 2^−23; both × K;
///   ROM 38's word (U9.16) ≤ 2^−17 off K, × the operand (≤ value + its error ≤ 1);
///   multiplier 39: ≤ 2^−21. `value` is the formula's (or cos^n where they agree).
double arithmetic_bound(long n, double k, double value = 1.0) {
  const double operand_error = std::ldexp(1.0, k_of(n) - 31) + std::ldexp(1.0, -23);
  return k * operand_error + std::ldexp(1.0, -17) * std::min(1.0, value + operand_error) +
         std::ldexp(1.0, -21);
}

double lobe_value(const variants::VariantResult& r) { return std::ldexp(static_cast<double>(r.lobe), -20); }
double pin_value(code_t code) { return std::ldexp(static_cast<double>(code), -13); }

variants::VariantResult run(const variants::Variant& v, long cos, long n, code_t i = 255) {
  Operands in;
  in.cos = cos;
  in.n = n;
  in.rgb = {i, i, i};
  return v.run(in);
}

TEST(VariantUs5739820, RegisteredUnderItsName) {
  const auto names = variants::variant_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "us5739820"), names.end());
  EXPECT_EQ(make_variant("us5739820")->name(), "us5739820");
}

TEST(VariantUs5739820, SquaringsAreLog2NRounded) {
  for (long n = 1; n <= 1023; ++n) ASSERT_EQ(variants::Us5739820::squarings(n), k_of(n)) << "n " << n;
}

// Every n on a slice of cos codes: the lobe within the arithmetic's bound of K·formula,
// pins 24–26 within 255× that plus their rounding (2^−14), and the lobe within the
// formula's own worst case (0.02801 at n = 3, x = 0.548, × K(3) = 2π/5) of K·cos^n.
TEST(VariantUs5739820, EveryNOnACosSliceIsWithinTheBounds) {
  const auto v = make_variant("us5739820");
  double worst_total = 0;
  long worst_n = 0;
  for (long n = 1; n <= 1000; ++n) {
    const double k = reference::k(static_cast<unsigned>(n), Normalisation::patent);
    for (long c = 0; c <= cos_one; c += (c >= cos_one - 64 ? 1 : 61)) {
      const double cos_q = std::ldexp(static_cast<double>(c), -16);
      const auto r = run(*v, c, n);
      const double want = k * formula(cos_q, n);
      const double bound = arithmetic_bound(n, k, formula(cos_q, n));
      ASSERT_LE(std::abs(lobe_value(r) - want), bound) << "cos code " << c << ", n " << n;
      for (code_t pin : r.out)
        ASSERT_LE(std::abs(pin_value(pin) - 255 * want), 255 * bound + std::ldexp(1.0, -14))
            << "cos code " << c << ", n " << n;
      const double total = std::abs(lobe_value(r) - k * reference::exact_lobe(cos_q, n));
      if (total > worst_total) worst_total = total, worst_n = n;
    }
  }
  EXPECT_LE(worst_total, 0.0352 + arithmetic_bound(3, 2 * M_PI / 5));
  EXPECT_EQ(worst_n, 3);
}

// cos 1: the base is 1 and stays 1, the lobe is ROM 38's K(n).
TEST(VariantUs5739820, CosOneGivesK) {
  const auto v = make_variant("us5739820");
  for (long n = 1; n <= 1000; ++n) {
    const double k = reference::k(static_cast<unsigned>(n), Normalisation::patent);
    ASSERT_LE(std::abs(lobe_value(run(*v, cos_one, n)) - k), std::ldexp(1.0, -17) + std::ldexp(1.0, -21))
        << "n " << n;
  }
}

// cos 0: 0 where 2^k ≤ n (the base reaches 0, clamped when 2^k < n), otherwise the
// formula's (1 − n/2^k)^(2^k) (n = 3: 1/256, the largest).
TEST(VariantUs5739820, CosZeroFollowsTheClamp) {
  const auto v = make_variant("us5739820");
  for (long n = 1; n <= 1000; ++n) {
    const double k = reference::k(static_cast<unsigned>(n), Normalisation::patent);
    const double lobe = lobe_value(run(*v, 0, n));
    if (std::ldexp(1.0, k_of(n)) <= n)
      ASSERT_EQ(lobe, 0.0) << "n " << n;
    else
      ASSERT_LE(std::abs(lobe - k * formula(0.0, n)), arithmetic_bound(n, k, formula(0.0, n))) << "n " << n;
  }
  EXPECT_NEAR(lobe_value(run(*v, 0, 3)), 2 * M_PI / 5 / 256, arithmetic_bound(3, 2 * M_PI / 5));
}

// n = 1: no squaring, the lobe is K(1)·cos itself (the approximation is exact).
TEST(VariantUs5739820, NOneIsExactOnEveryCosCode) {
  const auto v = make_variant("us5739820");
  const double k = reference::k(1, Normalisation::patent);
  for (long c = 0; c <= cos_one; ++c) {
    const double cos_q = std::ldexp(static_cast<double>(c), -16);
    ASSERT_LE(std::abs(lobe_value(run(*v, c, 1)) - k * cos_q), arithmetic_bound(1, k, cos_q)) << "cos code " << c;
  }
}

// n = 1000: ten squarings of 1 − x·1000/1024; the formula's error there is 0.0004.
TEST(VariantUs5739820, NThousandOnEveryCosCode) {
  const auto v = make_variant("us5739820");
  const double k = reference::k(1000, Normalisation::patent);
  for (long c = 0; c <= cos_one; ++c) {
    const double cos_q = std::ldexp(static_cast<double>(c), -16);
    const double lobe = lobe_value(run(*v, c, 1000));
    ASSERT_LE(std::abs(lobe - k * formula(cos_q, 1000)), arithmetic_bound(1000, k, formula(cos_q, 1000)))
        << "cos code " << c;
    ASSERT_LE(std::abs(lobe - k * reference::exact_lobe(cos_q, 1000)), 0.0004) << "cos code " << c;
  }
}

// Powers of two: k = log2 n and the base is cos itself: exact up to the arithmetic.
TEST(VariantUs5739820, PowersOfTwoAreExact) {
  const auto v = make_variant("us5739820");
  for (long n = 1; n <= 512; n *= 2) {
    const double k = reference::k(static_cast<unsigned>(n), Normalisation::patent);
    for (long c = 0; c <= cos_one; c += 7) {
      const double cos_q = std::ldexp(static_cast<double>(c), -16);
      ASSERT_LE(std::abs(lobe_value(run(*v, c, n)) - k * reference::exact_lobe(cos_q, n)),
                arithmetic_bound(n, k, reference::exact_lobe(cos_q, n)))
          << "cos code " << c << ", n " << n;
    }
  }
}

TEST(VariantUs5739820, OtherNormalisationsScaleByTheirK) {
  for (Normalisation policy : {Normalisation::energy, Normalisation::none}) {
    Config config;
    config.normalisation = policy;
    const auto v = make_variant("us5739820", config);
    for (long n : {1L, 3L, 100L, 1000L}) {
      const double k = reference::k(static_cast<unsigned>(n), policy);
      EXPECT_LE(std::abs(lobe_value(run(*v, cos_one, n)) - k), std::ldexp(1.0, -17) + std::ldexp(1.0, -21))
          << to_string(policy) << ", n " << n;
    }
  }
}

/// Expects make_variant to throw std::invalid_argument mentioning `needle`.
void expect_refused(const Config& config, const std::string& needle) {
  try {
    make_variant("us5739820", config);
    ADD_FAILURE() << "accepted a config with " << needle;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(VariantUs5739820, RefusesConfigsItIsNotBuiltFor) {
  Config widths;
  widths.widths.reg9_frac_bits = 24;
  expect_refused(widths, "reg9_frac_bits = 24");
  Config constants;
  constants.constants = Constants::minimax;
  expect_refused(constants, "constants minimax");
  Config literal;
  literal.saturation = Saturation::literal;
  expect_refused(literal, "saturation literal");
  Config energy;
  energy.normalisation = Normalisation::device_energy;
  expect_refused(energy, "device_energy (allowed: patent, energy, none");
}

// The unrolled version squares or passes y on at each stage: the same bits, its own name.
TEST(VariantUs5739820, PipelinedIsTheSameArithmetic) {
  const auto sequential = make_variant("us5739820");
  const auto pipelined = make_variant("us5739820_pipelined");
  EXPECT_EQ(pipelined->name(), "us5739820_pipelined");
  for (long n = 1; n <= 1000; n += 37)
    for (long c = 0; c <= cos_one; c += 997) {
      const auto a = run(*sequential, c, n), b = run(*pipelined, c, n);
      ASSERT_EQ(a.lobe, b.lobe) << "cos code " << c << ", n " << n;
      ASSERT_EQ(a.out, b.out) << "cos code " << c << ", n " << n;
    }
  Config literal;
  literal.saturation = Saturation::literal;
  EXPECT_THROW(make_variant("us5739820_pipelined", literal), std::invalid_argument);
}

TEST(VariantUs5739820, RefusesOperandsOffTheirBuses) {
  const auto v = make_variant("us5739820");
  EXPECT_THROW(run(*v, cos_one + 1, 1), std::out_of_range);
  EXPECT_THROW(run(*v, -1, 1), std::out_of_range);
  EXPECT_THROW(run(*v, 0, 1024), std::out_of_range);
  EXPECT_THROW(run(*v, 0, 1, 256), std::out_of_range);
}

}  // namespace
}  // namespace specular
