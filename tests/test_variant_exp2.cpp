// Variant exp2 (docs/variants/exp2.md): its exp2 unit and its lobe against the double
// reference K(n)·cos^n (reference.h), within the bound derived there; the special points
// (cos 0, cos 1, n = 1, n = 1000); the configurations it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "specular/reference.h"
#include "specular/variants/exp2.h"
#include "specular/variants/exp2_unit.h"
#include "specular/variants/variant.h"

namespace specular {
namespace {

using variants::Exp2Organisation;
using variants::Exp2Table;
using variants::Exp2Variant;
using variants::VariantResult;

constexpr code_t cos_one = code_t{1} << 16;   // register 1's 1.0
constexpr double reg9_lsb = 1.0 / (1 << 22);  // S14.22
constexpr double lobe_lsb = 1.0 / (1 << 20);  // S10.20
constexpr double ln2 = 0.69314718055994531;

/// The exp2 unit's own error bound for x < 0 (docs/variants/exp2.md): the chord between
/// table points h = 2^−A apart overshoots 2^f by at most (ln 2)²/8·h²·2^f < (ln 2)²/4·h²;
/// a table word, and the rounded product d·t, are each within ½ of 2^−V; the integer part
/// halves all that at least (x < 0 with f > 0 means floor(x) ≤ −1); the final rounding
/// adds ½ LSB of the result.
double unit_bound(const Exp2Organisation& o) {
  const double h = std::ldexp(1.0, -o.addr_bits);
  return (ln2 * ln2 / 4 * h * h + std::ldexp(1.0, -o.value_frac_bits)) / 2 +
         std::ldexp(0.5, -o.out_frac_bits);
}

/// The lobe's bound at (cos, n): multiplier 39 rounds (½ LSB), ROM 38's word is within
/// 2^−17 of K(n) and cos^n ≤ 1 multiplies it, and K(n) multiplies cos^n's error: the exp2
/// unit's, plus x's — ROM 5's word (½ of 2^−22) times n and multiplier 6's rounding,
/// (n + 1)·2^−23, which moves 2^x by up to 2^x·ln 2·|Δx|·2^|Δx|.
double lobe_bound(double cos_q, unsigned n, double k) {
  const double dx = (n + 1.0) * std::ldexp(1.0, -23);
  const double pow_error = unit_bound(Exp2Organisation{}) + std::pow(cos_q, n) * ln2 * dx * std::exp2(dx);
  return 0.5 * lobe_lsb + std::ldexp(1.0, -17) + k * pow_error;
}

Operands operands(code_t cos, unsigned n, code_t intensity = 255) {
  Operands in;
  in.cos = cos;
  in.n = n;
  in.rgb = {intensity, intensity, intensity};
  return in;
}

TEST(Exp2Unit, MeetsItsBoundOnEveryXOfTheTopThreeOctaves) {
  const Exp2Table unit;
  const double bound = unit_bound(unit.organisation());
  double worst = 0;
  // Every x code in [−3, 0): every table word with every interpolation fraction.
  for (code_t x = -3 * (code_t{1} << 22); x < 0; ++x) {
    const double error = std::fabs(unit.pow2(x) * reg9_lsb - std::exp2(x * reg9_lsb));
    worst = std::max(worst, error);
    ASSERT_LE(error, bound) << "x code " << x;
  }
  RecordProperty("worst_reg9_lsb", std::to_string(worst / reg9_lsb));
  EXPECT_GT(worst, bound / 4) << "the bound should be near what the unit does";
}

TEST(Exp2Unit, ExactAtZeroAndAtIntegers) {
  const Exp2Table unit;
  EXPECT_EQ(unit.pow2(0), code_t{1} << 22);
  EXPECT_EQ(unit.pow2(code_t{1} << 22), code_t{1} << 22) << "x > 0 reads as 0";
  for (int k = 1; k <= 22; ++k)
    EXPECT_EQ(unit.pow2(-(code_t{k} << 22)), code_t{1} << (22 - k)) << "x = −" << k;
  EXPECT_EQ(unit.pow2(-(code_t{23} << 22)), 1) << "2^−23 = ½ LSB rounds up";
  EXPECT_EQ(unit.pow2(-(code_t{24} << 22)), 0);
  EXPECT_EQ(unit.pow2(-(code_t{16384} << 22)), 0) << "register 9's most negative code";
}

TEST(Exp2Unit, TheTableFitsTheVerilogUnitsWords) {
  // rtl/design_space/exp2_unit.v's defaults: 2^9 words of VALUE_FRAC = 24 + DELTA_W = 16 bits. The largest
  // difference, 2^25·(1 − 2^(−1/512)) ≈ 45 400, needs 16 bits.
  const Exp2Table unit;
  EXPECT_EQ(unit.words().size(), 512u);
  EXPECT_EQ(unit.delta_bits(), 16);
  EXPECT_EQ(unit.word_bits(), 40);
  // Word 0 is {2^0 − 1 = 0, round(2^(1/512)·2^24) − 2^24}.
  EXPECT_EQ(unit.words()[0],
            static_cast<std::uint64_t>(std::llround(std::exp2(1.0 / 512) * (1 << 24)) - (1 << 24)));
}

TEST(Exp2Unit, RefusesAnOrganisationItCannotBuild) {
  Exp2Organisation o;
  o.addr_bits = 0;
  EXPECT_THROW(Exp2Table{o}, std::invalid_argument);
  o = Exp2Organisation{};
  o.value_frac_bits = o.out_frac_bits;
  try {
    Exp2Table table{o};
    FAIL() << "value_frac_bits = out_frac_bits taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("value_frac_bits = 22"), std::string::npos) << e.what();
  }
}

TEST(VariantExp2, LobeAndPinsWithinTheirBoundOnEveryNAndSampledCosCodes) {
  const auto variant = variants::make_variant("exp2");
  double worst = 0;
  long checked = 0;
  for (unsigned n = n_min; n <= n_max; ++n) {
    const double k = reference::k(n, Normalisation::patent);
    for (code_t c = 0; c <= cos_one; c += (c < cos_one - 512 ? 61 : 1)) {
      const double cos_q = c * std::ldexp(1.0, -16);
      const double want = k * reference::exact_lobe(cos_q, n);
      const VariantResult got = variant->run(operands(c, n));
      const double bound = lobe_bound(cos_q, n, k);
      const double error = std::fabs(got.lobe * lobe_lsb - want);
      worst = std::max(worst, error);
      ASSERT_LE(error, bound) << "cos code " << c << ", n " << n;
      // Pins 24–26: the lobe's error times 255, and multipliers 13–15's ½ LSB (2^−14).
      for (code_t pin : got.out)
        ASSERT_LE(std::fabs(pin * std::ldexp(1.0, -13) - want * 255), 255 * bound + std::ldexp(1.0, -14))
            << "cos code " << c << ", n " << n;
      ++checked;
    }
  }
  RecordProperty("worst_lobe_lsb", std::to_string(worst / lobe_lsb));
  EXPECT_GT(checked, 1000000);
}

TEST(VariantExp2, CosZeroGivesZeroForEveryN) {
  const auto variant = variants::make_variant("exp2");
  for (unsigned n = n_min; n <= n_max; ++n) {
    const VariantResult got = variant->run(operands(0, n));
    ASSERT_EQ(got.lobe, 0) << "n " << n;
    ASSERT_EQ(got.out, (std::array<code_t, 3>{0, 0, 0})) << "n " << n;
  }
}

TEST(VariantExp2, CosOneGivesKOfNForEveryN) {
  const Exp2Variant variant{Config{}};
  for (unsigned n = n_min; n <= n_max; ++n) {
    ASSERT_EQ(variant.cos_pow_n(operands(cos_one, n)), code_t{1} << 22) << "1^n = 1, n " << n;
    const double k = reference::k(n, Normalisation::patent);
    const double error = std::fabs(variant.run(operands(cos_one, n)).lobe * lobe_lsb - k);
    ASSERT_LE(error, 0.5 * lobe_lsb + std::ldexp(1.0, -17)) << "n " << n;
  }
}

TEST(VariantExp2, NOneFollowsCosOnEveryCode) {
  const Exp2Variant variant{Config{}};
  // n = 1: cos^1 = cos, so register 9's code is register 1's, to the unit's bound (x's
  // own error, 2·2^−23, moves it by at most ln 2·2^−22).
  const double bound = unit_bound(Exp2Organisation{}) + ln2 * std::ldexp(1.0, -22);
  for (code_t c = 1; c <= cos_one; ++c) {
    const double error = std::fabs(variant.cos_pow_n(operands(c, 1)) * reg9_lsb - c * std::ldexp(1.0, -16));
    ASSERT_LE(error, bound) << "cos code " << c;
  }
}

TEST(VariantExp2, NThousandOnEveryCode) {
  const auto variant = variants::make_variant("exp2");
  const double k = reference::k(1000, Normalisation::patent);
  for (code_t c = 0; c <= cos_one; ++c) {
    const double cos_q = c * std::ldexp(1.0, -16);
    const double want = k * reference::exact_lobe(cos_q, 1000);
    const double error = std::fabs(variant->run(operands(c, 1000)).lobe * lobe_lsb - want);
    ASSERT_LE(error, lobe_bound(cos_q, 1000, k)) << "cos code " << c;
  }
  // The last code below 1.0: 2^(1000·log2(1 − 2^−16)) = 0.98486, K(1000)·that on S10.20.
  EXPECT_NEAR(variant->run(operands(cos_one - 1, 1000)).lobe * lobe_lsb,
              2 * M_PI / 1002 * std::pow(1 - std::ldexp(1.0, -16), 1000), 2 * lobe_lsb);
}

TEST(VariantExp2, TakesTheNormalisationsOfROM38sBanks0To2) {
  for (const Normalisation policy : {Normalisation::patent, Normalisation::energy, Normalisation::none}) {
    Config config;
    config.normalisation = policy;
    const auto variant = variants::make_variant("exp2", config);
    const double k = reference::k(500, policy);
    const double got = variant->run(operands(cos_one, 500)).lobe * lobe_lsb;
    EXPECT_NEAR(got, k, 0.5 * lobe_lsb + std::ldexp(1.0, -17)) << to_string(policy);
  }
}

/// make_variant("exp2", config) throws std::invalid_argument whose text holds `needles`.
void expect_refused(const Config& config, std::initializer_list<const char*> needles) {
  try {
    variants::make_variant("exp2", config);
    ADD_FAILURE() << "configuration taken";
  } catch (const std::invalid_argument& e) {
    for (const char* needle : needles)
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what() << " lacks " << needle;
  }
}

TEST(VariantExp2, RefusesAConfigItIsNotBuiltFor) {
  Config widths;
  widths.widths.rom5_addr_bits = 14;
  expect_refused(widths, {"rom5_addr_bits = 14", "rom5_addr_bits = 15"});
  Config minimax;
  minimax.constants = Constants::minimax;
  expect_refused(minimax, {"minimax", "allowed: patent"});
  Config device_energy;
  device_energy.normalisation = Normalisation::device_energy;
  expect_refused(device_energy, {to_string(Normalisation::device_energy), "allowed: patent, energy, none"});
}

TEST(VariantExp2, RefusesOperandsOffTheirBuses) {
  const Exp2Variant variant{Config{}};
  EXPECT_THROW(variant.run(operands(cos_one + 1, 1)), std::out_of_range);
  EXPECT_THROW(variant.run(operands(1, 1024)), std::out_of_range);
  EXPECT_THROW(variant.run(operands(1, 1, 256)), std::out_of_range);
}

}  // namespace
}  // namespace specular
