// Variant schlick_divider's C++ model (variants/schlick_divider.h) against Schlick's
// formula x / (n − (n − 1)·x) in double, computed here: a restoring divider's quotient is
// exact, so register 9 is the formula rounded half up, within ½ LSB (2^-23); special
// points; refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "specular/core.h"
#include "specular/reference.h"
#include "specular/variants/schlick_divider.h"
#include "specular/variants/variant.h"

namespace {

using specular::code_t;
using specular::Config;
using specular::Operands;
using specular::variants::SchlickDivider;

constexpr double reg9_lsb = 1.0 / (1 << 22);
constexpr double lobe_lsb = 1.0 / (1 << 20);
constexpr double rom38_lsb = 1.0 / (1 << 16);
constexpr code_t cos_one = code_t{1} << 16;

double schlick(double x, unsigned n) { return x / (n - (n - 1.0) * x); }

Operands operands(code_t cos, unsigned n) {
  Operands in;
  in.cos = cos;
  in.n = n;
  in.rgb = {255, 128, 0};
  return in;
}

TEST(VariantSchlickDivider, Register9IsSchlicksFormulaRoundedToHalfAnLsb) {
  for (unsigned n = 1; n <= 1000; ++n)
    for (code_t c = 0; c <= cos_one; c += (c < 8 || c > cos_one - 8) ? 1 : 89) {
      const double error = SchlickDivider::cos_power(c, n) * reg9_lsb - schlick(c / 65536.0, n);
      // Half an LSB, plus double's own rounding of the formula (far below 2^-40).
      ASSERT_LE(std::fabs(error), reg9_lsb / 2 + 1e-12) << "cos code " << c << ", n " << n;
    }
}

TEST(VariantSchlickDivider, LobeAndPinsAreTheDevicesTailOfIt) {
  const SchlickDivider model{Config{}};
  for (unsigned n : {1u, 2u, 3u, 57u, 500u, 1000u}) {
    const double k = specular::reference::k(n, specular::Normalisation::patent);
    for (code_t c : {code_t{0}, code_t{1}, code_t{32768}, code_t{65372}, cos_one}) {
      const double a = schlick(c / 65536.0, n);
      const auto result = model.run(operands(c, n));
      EXPECT_NEAR(result.lobe * lobe_lsb, k * a, k * reg9_lsb / 2 + a * rom38_lsb / 2 + lobe_lsb / 2) << c << ", " << n;
      EXPECT_NEAR(result.out[0] / 8192.0, result.lobe * lobe_lsb * 255, 0.5 / 8192);
      EXPECT_NEAR(result.out[1] / 8192.0, result.lobe * lobe_lsb * 128, 0.5 / 8192);
      EXPECT_EQ(result.out[2], 0);
    }
  }
}

TEST(VariantSchlickDivider, SpecialPoints) {
  for (unsigned n = 1; n <= 1000; ++n) {
    EXPECT_EQ(SchlickDivider::cos_power(0, n), 0) << n;
    EXPECT_EQ(SchlickDivider::cos_power(cos_one, n), code_t{1} << 22) << n;  // 1.0
  }
  for (code_t c = 0; c <= cos_one; ++c) ASSERT_EQ(SchlickDivider::cos_power(c, 1), c << 6) << c;
}

TEST(VariantSchlickDivider, RefusesAConfigurationItIsNotBuiltFor) {
  Config widths;
  widths.widths.norm_frac_bits = 18;
  try {
    SchlickDivider model{widths};
    ADD_FAILURE() << "accepted norm_frac_bits = 18";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("schlick_divider: width norm_frac_bits = 18"), std::string::npos) << what;
    EXPECT_NE(what.find("allowed: "), std::string::npos) << what;
  }
  Config energy;
  energy.normalisation = specular::Normalisation::device_energy;
  EXPECT_THROW(specular::variants::make_variant("schlick_divider", energy), std::invalid_argument);
  Config constants;
  constants.constants = specular::Constants::minimax_half;
  EXPECT_THROW(SchlickDivider{constants}, std::invalid_argument);
  EXPECT_THROW(SchlickDivider{Config{}}.run(operands(0, 1001)), std::out_of_range);
}

}  // namespace
