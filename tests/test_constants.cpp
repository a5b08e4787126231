// The constants policy (issue 14): the frozen constants' errors recomputed in double
// on a dense grid, the codes pins 19 and 20 carry, the core against the double
// reference under each constants × normalisation policy on a sample with corners, and
// the patent's constants bit-identical to the device before pin 19 and ROM 38 grew.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "support/accuracy_sweep.h"
#include "support/pins_run.h"
#include "specular/constants.h"
#include "specular/core.h"
#include "specular/reference.h"

namespace specular {
namespace {

constexpr Constants every_constants[] = {Constants::patent, Constants::minimax_half,
                                         Constants::minimax};

/// max_x |s·max(0, a − h·log2(a + x)) − 2^−x| on x = 0, 10^−5, … 60, with s making
/// the peak 1: written here again, from the formula, not from the search.
double dense_grid_error(double a, double h) {
  const double s = 1.0 / (a - h * std::log2(a));
  double worst = 0;
  for (long i = 0; i <= 6000000; ++i) {
    const double x = i * 1e-5;
    worst = std::max(worst, std::abs(s * std::max(0.0, a - h * std::log2(a + x)) - std::exp2(-x)));
  }
  return worst;
}

TEST(FrozenConstants, ErrorRecomputedOnADenseGridMatchesTheSearch) {
  for (Constants c : every_constants) {
    const ConstantValues& v = constant_values(c);
    const double grid = dense_grid_error(v.a(), v.h());
    SCOPED_TRACE(to_string(c));
    // The grid samples: at most the true maximum, and within step × slope of it.
    EXPECT_LE(grid, v.max_error + 1e-9);
    EXPECT_GE(grid, v.max_error - 2e-5);
  }
  // The bounds on the approximation itself.
  EXPECT_NEAR(constant_values(Constants::patent).max_error, 0.125, 1e-12);
  EXPECT_LT(constant_values(Constants::minimax_half).max_error, 0.075);
  EXPECT_LT(constant_values(Constants::minimax).max_error, 0.042);
}

TEST(FrozenConstants, ValuesAreThoseOfTheTable) {
  // docs/study.md §5: patent 1, ½, 1; minimax-half a = 1.148987293, s = 0.953465295;
  // minimax a = 0.373026371, h = 41/256, s = 1.664245923.
  EXPECT_EQ(constant_values(Constants::patent).a(), 1.0);
  EXPECT_EQ(constant_values(Constants::patent).h(), 0.5);
  EXPECT_EQ(constant_values(Constants::patent).s(), 1.0);
  EXPECT_NEAR(constant_values(Constants::minimax_half).a(), 1.148987293, 1e-9);
  EXPECT_EQ(constant_values(Constants::minimax_half).h(), 0.5);
  EXPECT_NEAR(constant_values(Constants::minimax_half).s(), 0.953465295, 1e-9);
  EXPECT_NEAR(constant_values(Constants::minimax).a(), 0.373026371, 1e-9);
  EXPECT_EQ(constant_values(Constants::minimax).h(), 41.0 / 256);
  EXPECT_NEAR(constant_values(Constants::minimax).s(), 1.664245923, 1e-9);
}

TEST(PinCodes, PinsNineteenAndTwentyCarryTheConstantsInTheirBusFormats) {
  Config config;  // U10.8 on pin 19, S14.22 on pin 20
  EXPECT_EQ(pin19_code(config), 128);           // ½ · 2^8
  EXPECT_EQ(pin20_code(config), 1LL << 22);     // 1.0 · 2^22
  config.constants = Constants::minimax_half;
  EXPECT_EQ(pin19_code(config), 128);
  EXPECT_EQ(pin20_code(config), 4819202);
  config.constants = Constants::minimax;
  EXPECT_EQ(pin19_code(config), 41);
  EXPECT_EQ(pin20_code(config), 1564586);
  config.widths.reg9_frac_bits = 24;  // a wider bus holds the same values
  EXPECT_EQ(pin20_code(config), 1564586LL << 2);
}

TEST(PinCodes, BusesTooNarrowForTheConstantsAreRefusedByName) {
  Config config;
  config.constants = Constants::minimax;
  config.widths.pin19_frac_bits = 7;
  try {
    Core core(config);
    FAIL() << "a 7-bit pin 19 cannot hold 41/256";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pin19_frac_bits >= 8 (got 7)"), std::string::npos) << e.what();
  }
  config.constants = Constants::minimax_half;
  config.widths.pin19_frac_bits = 1;
  config.widths.reg9_frac_bits = 20;
  config.widths.cos_frac_bits = 16;
  EXPECT_THROW(Core{config}, std::invalid_argument);
  config.constants = Constants::patent;  // ½ and 1 fit any width
  EXPECT_NO_THROW(Core{config});
}

TEST(Rom38, AWordAboveItsFormatIsRefusedNotSaturated) {
  // energy × minimax: s·(n+2)/(2π) = 1.664245923·967/(2π) = 256.13 at n = 965, the first
  // word above U8.16's 256 − 2^-16: the reason ROM 38 is U9.16 now.
  Config config;
  config.widths.rom38_int_bits = 8;
  config.normalisation = Normalisation::energy;
  config.constants = Constants::minimax;
  try {
    Core core(config);
    FAIL() << "U8.16 cannot hold s·K(965)";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ROM 38 word for n = 965 is 256.13"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("widen rom38_int_bits"), std::string::npos) << e.what();
  }
  config.widths = Widths{};
  const Core core(config);  // U9.16 holds every word, n = 0 … 1023
  EXPECT_NEAR(static_cast<double>(core.rom38().k(1023)), 1.664245923 * 1025 / (2 * M_PI) * 65536, 1.0);
  // Address 0, never used: with n = 0 the lobe is flat at A = 1/s, so device-energy's
  // word 1/I(0) is s/π, as energy's s·2/(2π) is.
  config.normalisation = Normalisation::device_energy;
  const Core device_energy(config);
  EXPECT_NEAR(static_cast<double>(device_energy.rom38().k(0)), 1.664245923 / M_PI * 65536, 2.0);
  EXPECT_NEAR(static_cast<double>(device_energy.rom38().k(0)), static_cast<double>(core.rom38().k(0)), 2.0);
}

TEST(Rom38, AWordOnItsFormatsLargestCodeIsKeptAndTheFirstAboveIsRefused) {
  // U8.1 holds at most 255.5 (code 511). Energy × minimax, from the spec's formula
  // s·(n+2)/(2π), rounds to code 511 first at some n (kept: it fits) and above it two n
  // later (refused, named): the refusal must name the first word above the largest code,
  // not the first word on it (cpp_mutants.py's arith.cpp `>` -> `>=` mutant).
  const double s = 1.664245923;
  auto word = [&](unsigned n) { return std::llround(2.0 * s * (n + 2) / (2 * M_PI)); };
  unsigned on_largest = 0, above = 0;
  for (unsigned n = 1; n <= 1000 && above == 0; ++n) {
    if (word(n) == 511 && on_largest == 0) on_largest = n;
    if (word(n) > 511) above = n;
  }
  ASSERT_NE(on_largest, 0u) << "no n rounds onto U8.1's largest code: the test needs another format";
  ASSERT_GT(above, on_largest);
  Config config;
  config.widths.rom38_int_bits = 8;
  config.widths.rom38_frac_bits = 1;
  config.normalisation = Normalisation::energy;
  config.constants = Constants::minimax;
  try {
    Core core(config);
    FAIL() << "U8.1 cannot hold s·K(" << above << ")";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ROM 38 word for n = " + std::to_string(above) + " is"),
              std::string::npos)
        << e.what();
  }
}

TEST(Rom38, DeviceEnergyWordsAreOneOverTheDevicesOwnLobe) {
  // device-energy: K(n) = 1/I(n), I(n) the integral over cos of the device's own lobe A
  // (register 9 after pass 2, clamp). Summed here over every cos code of the core's results
  // (from cos = 1 down, as a sum must run to round alike), each A weighed by the double
  // reference's code interval; the word must be exactly round(2^F / I(n)). At w20 (register
  // 9 with 16 fraction bits) the A of 1 LSB weigh enough to move a word at some n: the
  // lobe ends at A = 0, not at 1 LSB (C++ mutant arith.cpp `a <= 0` -> `a <= 1`). The n:
  // the eight where ending at 1 LSB moves a word (found by building both tables), and four
  // others.
  Config config;
  config.widths.rom5_word_bits = 20;
  config.widths.reg9_frac_bits = 16;
  config.normalisation = Normalisation::device_energy;
  const Core core(config);
  const Formats& f = core.formats();
  for (unsigned n : {1u, 2u, 100u, 407u, 627u, 651u, 705u, 720u, 756u, 830u, 926u, 1000u}) {
    double integral = 0;
    for (code_t c = f.cos.one(); c >= 0; --c) {
      Operands in;
      in.cos = c;
      in.n = n;
      const code_t a = core.run(in).reg9_pass2;
      if (a > 0) integral += f.reg9.to_real(a) * reference::code_interval_integral(c, f.cos.frac_bits);
    }
    EXPECT_EQ(core.rom38().k(n), std::llround(std::ldexp(1.0 / integral, f.rom38.frac_bits))) << "n = " << n;
  }
}

TEST(LiteralSaturation, AProductOnMultiplier39sMinimumFitsAndTheFirstBelowIsRefused) {
  // Under `literal` the lowest K·A, (a − h·log2(a + n·F))·K(n) at cos code 0, must stay
  // inside multiplier 39's format. With normalisation none (K = 1), patent constants
  // (a = 1, h = ½) and 3 cos fraction bits, 1 + 3n = 64 at n = 21 puts it exactly on
  // S1.F's minimum −2: it fits; the refusal must name the first n below it (C++ mutant
  // arith.cpp `lowest < min` -> `<=`).
  unsigned on_minimum = 0, below = 0;
  for (unsigned n = 1; n <= 1000 && below == 0; ++n) {
    const double lowest = 1.0 - 0.5 * std::log2(1.0 + 3.0 * n);
    if (lowest == -2.0 && on_minimum == 0) on_minimum = n;
    if (lowest < -2.0) below = n;
  }
  ASSERT_EQ(on_minimum, 21u);
  ASSERT_GT(below, on_minimum);
  Config config;
  config.widths.cos_frac_bits = 3;
  config.widths.norm_int_bits = 1;
  config.normalisation = Normalisation::none;
  config.saturation = Saturation::literal;
  try {
    Core core(config);
    FAIL() << "S1 cannot hold K·A at n = " << below;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(" at n = " + std::to_string(below) + ","), std::string::npos)
        << e.what();
  }
}

TEST(PatentConstants, BitIdenticalToTheDeviceBeforePin19AndRom38Grew) {
  // Today's device: pin 19 U10.8, ROM 38 U9.16. Before issue 14: U10.1 and U8.16.
  Config before;
  before.widths.pin19_frac_bits = 1;
  before.widths.rom38_int_bits = 8;
  for (Normalisation norm : {Normalisation::patent, Normalisation::energy, Normalisation::none})
    for (Saturation sat : {Saturation::clamp, Saturation::literal}) {
      before.normalisation = norm;
      before.saturation = sat;
      Config now = before;
      now.widths = Widths{};
      const Core old_core(before), new_core(now);
      ASSERT_TRUE(new_core.uses_default_formats());
      const auto codes = testing_support::cos_codes(new_core.formats(), 37);
      for (unsigned n = 1; n <= 1000; n += (n < 20 ? 1 : 13)) {
        for (code_t c : codes) {
          Operands in;
          in.cos = c;
          in.n = n;
          in.rgb = {255, 128, 1};
          const Result a = old_core.run(in), b = new_core.run(in);
          ASSERT_EQ(a.reg9_pass1, b.reg9_pass1) << "n " << n << " code " << c;
          ASSERT_EQ(a.reg9_pass2, b.reg9_pass2) << "n " << n << " code " << c;
          ASSERT_EQ(a.rom38_k, b.rom38_k);
          ASSERT_EQ(a.norm39, b.norm39);
          ASSERT_EQ(a.out, b.out);
        }
      }
    }
}

class ConstantsSampled
    : public ::testing::TestWithParam<std::tuple<Constants, Normalisation, Saturation>> {};

TEST_P(ConstantsSampled, CoreMeetsTheBoundsAgainstTheReference) {
  Config config;
  std::tie(config.constants, config.normalisation, config.saturation) = GetParam();
  const Formats formats(config.widths);
  if (config.constants == Constants::patent && config.normalisation == Normalisation::device_energy &&
      config.saturation == Saturation::literal) {
    // K·A would reach −1178 below S10.20's −1024: refused, not saturated.
    try {
      Core core(config);
      FAIL() << "device-energy × literal × patent constants must be refused";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("below multiplier 39's S10.20 minimum -1024"),
                std::string::npos) << e.what();
    }
    return;
  }
  const testing_support::SweepFigures s =
      testing_support::sweep(config, testing_support::cos_codes(formats, 257));
  std::cout << testing_support::summary(config, s) << std::endl;
  EXPECT_EQ(s.approx_misses, 0) << s.first_miss;
  EXPECT_EQ(s.norm_misses, 0) << s.first_miss;
  EXPECT_EQ(s.out_misses, 0) << s.first_miss;
  EXPECT_EQ(s.pass1_misses, 0) << s.first_miss;
  if (config.saturation == Saturation::clamp) {
    // The device's own approximation s·A of cos_q^n (issue 14 item 4).
    const double bound = config.constants == Constants::minimax        ? 0.042
                         : config.constants == Constants::minimax_half ? 0.075
                                                                       : 0.125 + 1e-4;
    EXPECT_LE(s.lobe_exact.error, bound);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Policies, ConstantsSampled,
    ::testing::Combine(::testing::Values(Constants::patent, Constants::minimax_half, Constants::minimax),
                       ::testing::Values(Normalisation::patent, Normalisation::energy,
                                         Normalisation::none, Normalisation::device_energy),
                       ::testing::Values(Saturation::clamp, Saturation::literal)),
    [](const auto& info) {
      std::string name = std::string(to_string(std::get<0>(info.param))) + "_" +
                         to_string(std::get<1>(info.param)) + "_" + to_string(std::get<2>(info.param));
      for (char& ch : name)
        if (ch == '-') ch = '_';
      return name;
    });

TEST(ConstantsNames, ParseAndPrintRoundTripAndBadNamesAreRefused) {
  for (Constants c : every_constants) EXPECT_EQ(parse_constants(to_string(c)), c);
  EXPECT_EQ(parse_normalisation("device-energy"), Normalisation::device_energy);
  try {
    parse_constants("minmax");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "constants policy 'minmax' is not one of: patent, minimax-half, minimax");
  }
  EXPECT_THROW(parse_normalisation("device_energy"), std::invalid_argument);
}

}  // namespace
}  // namespace specular

namespace specular {
namespace {

// The pin harness ties pins 19 and 20 to the policy's constants: the pin model under
// minimax equals the core on corners and a sample (the long tests do the whole sweep),
// and the pins carry the codes the policy names.
TEST(PinModel, MinimaxConstantsOnThePinsGiveTheCoresResults) {
  Config config;
  config.constants = Constants::minimax;
  config.normalisation = Normalisation::device_energy;
  const Core core(config);
  std::vector<Operands> ops;
  for (unsigned n : {1u, 2u, 17u, 500u, 1000u})
    for (code_t c : {code_t{0}, code_t{1}, code_t{30000}, code_t{65000}, code_t{65535}, code_t{65536}}) {
      Operands in;
      in.cos = c;
      in.n = n;
      in.rgb = {255, 128, 1};
      ops.push_back(in);
    }
  PinHarness harness("harness", config, sc_core::sc_time(10, sc_core::SC_NS));
  testing_support::PinDriver driver("driver", harness, ops);
  sc_core::sc_start();
  EXPECT_EQ(harness.pin19_h.read(), 41);       // h = 41/256 on U10.8
  EXPECT_EQ(harness.pin20_a.read(), 1564586);  // a on S14.22
  ASSERT_EQ(driver.out.results.size(), ops.size());
  for (std::size_t i = 0; i < ops.size(); ++i) {
    const Result want = core.run(ops[i]);
    const Result& got = driver.out.results[i];
    EXPECT_EQ(got.reg9_pass1, want.reg9_pass1) << i;
    EXPECT_EQ(got.reg9_pass2, want.reg9_pass2) << i;
    EXPECT_EQ(got.rom38_k, want.rom38_k) << i;
    EXPECT_EQ(got.out, want.out) << i;
  }
}

}  // namespace
}  // namespace specular
