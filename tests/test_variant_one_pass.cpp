// Variants one_pass and one_pass_pipelined (issue 26, docs/variants/one_pass.md): their
// C++ model (two ROM 5s, pass 1 then pass 2) against the double reference within the
// bound derived below, equal to the patent's device on every n × a cos slice and under
// every policy it builds, its special points, and its refusal of widths it is not built for.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "specular/constants.h"
#include "specular/reference.h"
#include "specular/variants/variant.h"

namespace specular {
namespace {

using variants::VariantResult;
using variants::make_variant;

const char* const one_pass_names[] = {"one_pass", "one_pass_pipelined"};
constexpr code_t cos_one = code_t{1} << 16;
const double lobe_lsb = std::ldexp(1.0, -20);  // multiplier 39's S10.20
const double out_lsb = std::ldexp(1.0, -13);   // pins 24–26, S18.13

Operands operands(code_t cos, unsigned n, code_t intensity = 255) {
  Operands in;
  in.cos = cos;
  in.n = n;
  in.rgb = {intensity, intensity, intensity};
  return in;
}

/// The fixed-point error of K·A against the double formula K(n)·approx (patent
/// constants, default widths), term by term (docs/variants/one_pass.md, "Error"):
///   pass 1: ROM 5's word rounding (n·2^−23) and multiplier 6's (2^−23): X̂ − X;
///   pass 2: log2 X̂ − log2 X ≤ |X̂ − X|/(X·ln 2) with X ≥ 1, ROM 5's 15-bit address
///           truncation (< 2^−15/ln 2) and word rounding (2^−23), all × h = ½, plus
///           multiplier 6's rounding (2^−23): Â − A;
///   tail:   K(n)·|Â − A| + A·(ROM 38's rounding 2^−17) + multiplier 39's (2^−21), A ≤ 1.
double fixed_point_bound(unsigned n) {
  const double k = reference::k(n, Normalisation::patent);
  const double ulp23 = std::ldexp(1.0, -23);
  const double pass1 = (n + 1) * ulp23;
  const double pass2 = 0.5 * (pass1 / std::log(2.0) + std::ldexp(1.0, -15) / std::log(2.0) + ulp23) + ulp23;
  return k * pass2 + std::ldexp(1.0, -17) + std::ldexp(1.0, -21);
}

TEST(OnePass, RegistersBothNames) {
  for (const char* name : one_pass_names) EXPECT_EQ(make_variant(name)->name(), name);
}

// The double reference K(n)·cos^n: the patent's formula error (constants' max_error,
// 0.125 at x = −n·log2 cos = 3) scaled by K(n), plus the fixed-point bound; and against
// the double formula K(n)·approx the fixed-point bound alone. Pins 24–26 at R = G = B =
// 255: 255 × that, plus multipliers 13–15's rounding (half an LSB of S18.13).
TEST(OnePass, ErrorAgainstTheDoubleReferenceWithinTheDerivedBound) {
  const auto model = make_variant("one_pass");
  const double formula_error = constant_values(Constants::patent).max_error;
  for (unsigned n = 1; n <= 1000; n += (n < 20 ? 1 : 37)) {
    const double k = reference::k(n, Normalisation::patent);
    const double bound = fixed_point_bound(n);
    for (code_t c = 0; c <= cos_one; c += (c < 64 || c > cos_one - 64) ? 1 : 61) {
      const double cos_q = std::ldexp(static_cast<double>(c), -16);
      const double exact = k * reference::exact_lobe(cos_q, n);
      const double formula = k * reference::approx(cos_q, n, Saturation::clamp, 16);
      const VariantResult got = model->run(operands(c, n));
      const double lobe = got.lobe * lobe_lsb;
      SCOPED_TRACE("cos code " + std::to_string(c) + ", n " + std::to_string(n));
      ASSERT_LE(std::abs(lobe - formula), bound);
      ASSERT_LE(std::abs(lobe - exact), k * formula_error + bound);
      for (const code_t pin : got.out)
        ASSERT_LE(std::abs(pin * out_lsb - 255 * exact), 255 * (k * formula_error + bound) + out_lsb / 2);
    }
  }
}

// cos λ = 0 (code 0: log2 0 := −16, A = 1 − ½·log2(1 + 16n) < 0, clamped): no light.
TEST(OnePass, CosZeroGivesNoLight) {
  const auto model = make_variant("one_pass");
  for (unsigned n : {1u, 2u, 500u, 1000u}) {
    const VariantResult got = model->run(operands(0, n));
    EXPECT_EQ(got.lobe, 0) << "n " << n;
    for (const code_t pin : got.out) EXPECT_EQ(pin, 0) << "n " << n;
  }
}

// cos λ = 1: log2 1 = 0 in both passes, A = 1 exactly, the lobe is K(n) = 2π/(n + 2)
// within ROM 38's and multiplier 39's rounding; pins 24–26 K(n)·255.
TEST(OnePass, CosOneGivesK) {
  const auto model = make_variant("one_pass");
  for (unsigned n : {1u, 2u, 500u, 1000u}) {
    const double k = 2 * M_PI / (n + 2);
    const VariantResult got = model->run(operands(cos_one, n));
    EXPECT_NEAR(got.lobe * lobe_lsb, k, std::ldexp(1.0, -17) + std::ldexp(1.0, -21)) << "n " << n;
    for (const code_t pin : got.out)
      EXPECT_NEAR(pin * out_lsb, 255 * k, 255 * (std::ldexp(1.0, -17) + std::ldexp(1.0, -21)) + out_lsb / 2);
  }
}

// n = 1 and n = 1000 at cos values whose A is known in closed form: cos = 2^−1 with
// n = 1 gives X = 2, A = ½; cos = 2^(−3/1000) with n = 1000 gives X = 4, A = 0;
// cos = 2^(−1/1000) gives X = 2, A = ½ (the nearest code, so within the bound).
TEST(OnePass, NOneAndNThousandAtKnownPoints) {
  const auto model = make_variant("one_pass");
  const auto lobe_of = [&](double cos, unsigned n) {
    return model->run(operands(std::lround(std::ldexp(cos, 16)), n)).lobe * lobe_lsb;
  };
  EXPECT_NEAR(lobe_of(0.5, 1), 0.5 * 2 * M_PI / 3, fixed_point_bound(1));
  // Rounding cos to 16 bits moves X by n·|Δlog2 cos| ≤ 1000·2^−17/(cos·ln 2).
  const double cos_step = 1000 * std::ldexp(1.0, -17) / (0.997 * std::log(2.0));
  const double k1000 = 2 * M_PI / 1002;
  EXPECT_NEAR(lobe_of(std::exp2(-0.001), 1000), 0.5 * k1000,
              k1000 * 0.5 * cos_step / (2 * std::log(2.0)) + fixed_point_bound(1000));
  EXPECT_NEAR(lobe_of(std::exp2(-0.003), 1000), 0.0,
              k1000 * 0.5 * cos_step / (4 * std::log(2.0)) + fixed_point_bound(1000));
}

// The arithmetic is the device's: the same bits as the patent's two passes on one ROM 5,
// every n on a cos slice, and under every policy the variants accept on a coarser grid.
TEST(OnePass, EqualsThePatentsDeviceOnEveryNAndACosSlice) {
  const auto patent = make_variant("patent");
  for (const char* name : one_pass_names) {
    const auto model = make_variant(name);
    for (unsigned n = 1; n <= 1000; ++n)
      for (code_t c = 0; c <= cos_one; c += (c < 3 || c > cos_one - 3) ? 1 : 251) {
        const Operands in = operands(c, n, (c + n) & 255);
        const VariantResult want = patent->run(in), got = model->run(in);
        ASSERT_EQ(got.lobe, want.lobe) << name << ": cos code " << c << ", n " << n;
        ASSERT_EQ(got.out, want.out) << name << ": cos code " << c << ", n " << n;
      }
  }
}

TEST(OnePass, EqualsThePatentsDeviceUnderEveryPolicy) {
  for (Constants constants : {Constants::patent, Constants::minimax_half, Constants::minimax})
    for (Normalisation norm : {Normalisation::patent, Normalisation::energy, Normalisation::none,
                               Normalisation::device_energy})
      for (Saturation saturation : {Saturation::clamp, Saturation::literal}) {
        Config config;
        config.constants = constants;
        config.normalisation = norm;
        config.saturation = saturation;
        SCOPED_TRACE(std::string(to_string(constants)) + ", " + to_string(norm) + ", " + to_string(saturation));
        std::unique_ptr<variants::Variant> patent;
        try {
          patent = make_variant("patent", config);
        } catch (const std::invalid_argument&) {  // a ROM 38 word that would not fit
          EXPECT_THROW(make_variant("one_pass", config), std::invalid_argument);
          continue;
        }
        const auto model = make_variant("one_pass", config);
        for (unsigned n = 1; n <= 1000; n += 37)
          for (code_t c = 0; c <= cos_one; c += 509) {
            const Operands in = operands(c, n, 200);
            const VariantResult want = patent->run(in), got = model->run(in);
            ASSERT_EQ(got.lobe, want.lobe) << "cos code " << c << ", n " << n;
            ASSERT_EQ(got.out, want.out) << "cos code " << c << ", n " << n;
          }
      }
}

TEST(OnePass, RefusesWidthsOtherThanTheDefault) {
  Config config;
  config.widths.rom5_addr_bits = 14;
  for (const char* name : one_pass_names) {
    try {
      (void)make_variant(name, config);
      FAIL() << name << " took rom5_addr_bits = 14";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("rom5_addr_bits = 14"), std::string::npos) << what;
      EXPECT_NE(what.find("rom5_addr_bits = 15"), std::string::npos) << what;  // what is allowed
      EXPECT_NE(what.find(name), std::string::npos) << what;
    }
  }
}

TEST(OnePass, RefusesOperandsOffTheirBuses) {
  const auto model = make_variant("one_pass");
  EXPECT_THROW(model->run(operands(code_t{1} << 17, 1)), std::out_of_range);  // beyond U1.16's 17 bits
  EXPECT_THROW(model->run(operands(0, 1024)), std::out_of_range);
  EXPECT_THROW(model->run(operands(0, 1, 256)), std::out_of_range);
}

}  // namespace
}  // namespace specular
