// format.h input checks (issue 2 item 10): a bad value is refused with a message that
// names the value and the allowed range; good values quantise as the spec says.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "specular/core.h"
#include "specular/format.h"

namespace specular {
namespace {

template <typename Exception, typename F>
::testing::AssertionResult throws_naming(F&& f, std::initializer_list<std::string> parts) {
  try {
    f();
  } catch (const Exception& e) {
    const std::string m = e.what();
    for (const std::string& part : parts)
      if (m.find(part) == std::string::npos)
        return ::testing::AssertionFailure() << "message '" << m << "' lacks '" << part << "'";
    return ::testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "wrong exception type: " << e.what();
  }
  return ::testing::AssertionFailure() << "no exception";
}

TEST(FormatInputs, CosQuantisesToNearestCode) {
  const Formats f;
  EXPECT_EQ(quantise_cos(f, 0.0), 0);
  EXPECT_EQ(quantise_cos(f, 1.0), 65536);
  EXPECT_EQ(quantise_cos(f, 0.5), 32768);
  EXPECT_EQ(quantise_cos(f, 1.0 / 3.0), 21845);       // 21845.33 → down
  EXPECT_EQ(quantise_cos(f, 2.0 / 3.0), 43691);       // 43690.67 → up
  EXPECT_EQ(quantise_cos(f, 1.0 - std::ldexp(1.0, -18)), 65536);  // rounds up to 1.0
  EXPECT_EQ(quantise_cos(f, std::ldexp(1.0, -18)), 0);
  EXPECT_EQ(quantise_cos(f, std::ldexp(1.0, -16)), 1);
  Widths w;
  w.cos_frac_bits = 8;
  EXPECT_EQ(quantise_cos(Formats(w), 0.75), 192);
}

TEST(FormatInputs, CosOutsideZeroOneIsRefusedWithValueAndRange) {
  const Formats f;
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { quantise_cos(f, -0.25); },
                                               {"cos", "-0.25", "[0, 1]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { quantise_cos(f, 1.5); },
                                               {"cos", "1.5", "[0, 1]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { quantise_cos(f, 1.0000001); },
                                               {"cos", "1.0000001", "[0, 1]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>(
      [&] { quantise_cos(f, std::numeric_limits<double>::quiet_NaN()); }, {"cos", "nan", "[0, 1]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>(
      [&] { quantise_cos(f, std::numeric_limits<double>::infinity()); }, {"cos", "inf", "[0, 1]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>(
      [&] { quantise_cos(f, -std::numeric_limits<double>::infinity()); }, {"cos", "-inf"}));
}

TEST(FormatInputs, NOutsideOneToThousandIsRefused) {
  EXPECT_EQ(check_n(1), 1u);
  EXPECT_EQ(check_n(1000), 1000u);
  EXPECT_EQ(check_n(500), 500u);
  EXPECT_TRUE(throws_naming<std::out_of_range>([] { check_n(0); }, {"n", "0", "[1, 1000]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>([] { check_n(1001); }, {"1001", "[1, 1000]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>([] { check_n(-7); }, {"-7", "[1, 1000]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>([] { check_n(1LL << 40); },
                                               {"1099511627776", "[1, 1000]"}));
}

TEST(FormatInputs, RgbOutsideItsFormatIsRefusedNamingTheChannel) {
  const Formats f;
  EXPECT_EQ(check_rgb(f, 0, "R"), 0u);
  EXPECT_EQ(check_rgb(f, 255, "G"), 255u);
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { check_rgb(f, 256, "G"); },
                                               {"G", "256", "[0, 255]"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { check_rgb(f, -1, "B"); },
                                               {"B", "-1", "[0, 255]"}));
  Widths w;
  w.rgb_bits = 10;
  EXPECT_EQ(check_rgb(Formats(w), 1023, "R"), 1023u);
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { check_rgb(Formats(w), 1024, "R"); },
                                               {"R", "1024", "[0, 1023]"}));
}

TEST(FormatInputs, CosCodeOutsideZeroToOneIsRefused) {
  const Formats f;
  EXPECT_EQ(check_cos_code(f, 0), 0);
  EXPECT_EQ(check_cos_code(f, 65536), 65536);
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { check_cos_code(f, 65537); },
                                               {"cos code", "65537", "65536"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { check_cos_code(f, -1); },
                                               {"cos code", "-1"}));
}

TEST(FormatInputs, PolicyNamesParseAndUnknownNamesListTheChoices) {
  for (auto p : {Normalisation::patent, Normalisation::energy, Normalisation::none})
    EXPECT_EQ(parse_normalisation(to_string(p)), p);
  for (auto s : {Saturation::clamp, Saturation::literal})
    EXPECT_EQ(parse_saturation(to_string(s)), s);
  EXPECT_TRUE(throws_naming<std::invalid_argument>([] { parse_normalisation("Patent"); },
                                                   {"'Patent'", "patent", "energy", "none"}));
  EXPECT_TRUE(throws_naming<std::invalid_argument>([] { parse_saturation("wrap"); },
                                                   {"'wrap'", "clamp", "literal"}));
}

TEST(FormatInputs, CoreOperandsCheckEveryValue) {
  const Core core;
  const Operands in = core.operands(0.5, 20, 255, 128, 0);
  EXPECT_EQ(in.cos, 32768);
  EXPECT_EQ(in.n, 20);
  EXPECT_EQ(in.rgb[0], 255);
  EXPECT_EQ(in.rgb[1], 128);
  EXPECT_EQ(in.rgb[2], 0);
  EXPECT_THROW(core.operands(std::nan(""), 20, 1, 1, 1), std::out_of_range);
  EXPECT_THROW(core.operands(0.5, 0, 1, 1, 1), std::out_of_range);
  EXPECT_THROW(core.operands(0.5, 20, 1, 1, 300), std::out_of_range);
}

// Core::run takes codes, not user values: a code off its input bus (which operands()
// never builds) is refused naming the register, the code and the bus's range, on both
// paths, rather than computed on a multiplier that assumes it fits (arith.h).
TEST(FormatInputs, CoreRunRefusesCodesOffTheirBuses) {
  const Core core;
  const Operands good = core.operands(0.5, 10, 1, 2, 3);
  EXPECT_NO_THROW(core.run(good));
  Operands in = good;
  in.rgb[0] = 256;
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { core.run(in); },
                                               {"register 10 (R)", "256", "U8.0", "0 to 255"}));
  in = good;
  in.rgb[1] = 256;  // G alone: each register's own check names it (a mutant checked B twice)
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { core.run(in); }, {"register 11 (G)", "256"}));
  in = good;
  in.rgb[2] = -1;
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { core.run(in); }, {"register 12 (B)", "-1"}));
  in = good;
  in.n = 1024;
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { core.run_generic(in); },
                                               {"register 2 (n)", "1024", "0 to 1023"}));
  in = good;
  in.cos = std::int64_t{1} << 17;
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { core.run(in); },
                                               {"register 1 (cos)", "131072", "U1.16", "0 to 131071"}));
  // The largest code of every bus is still on it.
  EXPECT_NO_THROW(core.run(Operands{(std::int64_t{1} << 17) - 1, 1023, {255, 255, 255}}));
  // The refusal names the operand off its bus, not one on its bus's edge (two mutants of
  // the check, < to <= and > to >=, named COS at code 0 or 131071 instead).
  EXPECT_TRUE(throws_naming<std::out_of_range>(
      [&] { core.run(Operands{(std::int64_t{1} << 17) - 1, 1024, {0, 0, 0}}); }, {"register 2 (n)", "1024"}));
  EXPECT_TRUE(throws_naming<std::out_of_range>([&] { core.run(Operands{0, 0, {256, 0, 0}}); },
                                               {"register 10 (R)", "256"}));
}

}  // namespace
}  // namespace specular
