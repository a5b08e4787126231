// format.h: every bus format derives from the designer's Widths (issue 2 item 3), and
// a bad width is refused with a message naming the width, its value and its range.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "specular/constants.h"
#include "specular/format.h"

namespace specular {
namespace {

::testing::AssertionResult refused_naming(const Widths& w, const std::string& width_name,
                                          const std::string& value, const std::string& range) {
  try {
    w.validate();
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    for (const std::string& part : {width_name, value, range})
      if (m.find(part) == std::string::npos)
        return ::testing::AssertionFailure() << "message '" << m << "' lacks '" << part << "'";
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << width_name << " = " << value << " was accepted";
}

TEST(FormatWidths, DefaultsAreTheDesignNotesFormats) {
  const Formats f;
  EXPECT_EQ(f.cos.name(), "U1.16");
  EXPECT_EQ(f.n.name(), "U10.0");
  EXPECT_EQ(f.rgb.name(), "U8.0");
  EXPECT_EQ(f.mux4.name(), "U10.8");  // h = 41/256 under minimax (issue 14)
  EXPECT_EQ(f.log2.name(), "S5.22");
  EXPECT_EQ(f.reg9.name(), "S14.22");
  EXPECT_EQ(f.rom38.name(), "U9.16");  // s·(n+2)/(2π) reaches 272
  EXPECT_EQ(f.norm.name(), "S10.20");
  EXPECT_EQ(f.out.name(), "S18.13");
  EXPECT_EQ(f.out.width(), 32);
  EXPECT_EQ(f.rom5_words(), 1 << 15);
  EXPECT_EQ(f.rom5_bits(), 32768L * 22);
  EXPECT_EQ(f.rom38_words(), 1024);
  EXPECT_EQ(f.rom38_bits(), 1024L * 25);
}

TEST(FormatWidths, FixedFormatMapsCodesToReals) {
  const FixedFormat s{true, 3, 4};  // S3.4: 8 bits, −8 .. 7.9375
  EXPECT_EQ(s.width(), 8);
  EXPECT_EQ(s.max_code(), 127);
  EXPECT_EQ(s.min_code(), -128);
  EXPECT_EQ(s.one(), 16);
  EXPECT_DOUBLE_EQ(s.to_real(-128), -8.0);
  EXPECT_DOUBLE_EQ(s.to_real(127), 7.9375);
  EXPECT_DOUBLE_EQ(s.lsb(), 0.0625);
  const FixedFormat u{false, 1, 16};
  EXPECT_EQ(u.width(), 17);
  EXPECT_EQ(u.min_code(), 0);
  EXPECT_DOUBLE_EQ(u.to_real(u.one()), 1.0);
}

TEST(FormatWidths, BusFormatsFollowTheirWidths) {
  Widths w;
  w.cos_frac_bits = 12;
  w.n_bits = 11;
  w.rgb_bits = 10;
  w.pin19_frac_bits = 3;
  w.rom5_addr_bits = 13;
  w.rom5_word_bits = 20;
  w.reg9_int_bits = 15;
  w.reg9_frac_bits = 26;
  w.rom38_int_bits = 9;
  w.rom38_frac_bits = 18;
  w.norm_int_bits = 11;
  w.norm_frac_bits = 24;
  w.out_int_bits = 20;
  w.out_frac_bits = 10;
  const Formats f(w);
  EXPECT_EQ(f.cos.name(), "U1.12");
  EXPECT_EQ(f.n.name(), "U11.0");
  EXPECT_EQ(f.rgb.name(), "U10.0");
  EXPECT_EQ(f.mux4.name(), "U11.3");
  EXPECT_EQ(f.reg9.name(), "S15.26");
  EXPECT_EQ(f.rom38.name(), "U9.18");
  EXPECT_EQ(f.norm.name(), "S11.24");
  EXPECT_EQ(f.out.name(), "S20.10");
  EXPECT_EQ(f.log2.frac_bits, 20);
  EXPECT_EQ(f.rom5_words(), 1 << 13);
  EXPECT_EQ(f.rom38_words(), 1 << 11);
  // The wired constants follow the formats they sit on.
  EXPECT_DOUBLE_EQ(f.mux4.to_real(pin19_code(f, Constants::patent)), 0.5);
  EXPECT_DOUBLE_EQ(f.reg9.to_real(pin20_code(f, Constants::patent)), 1.0);
  EXPECT_DOUBLE_EQ(f.reg9.to_real(pin20_code(f, Constants::minimax_half)), 4819202.0 / (1 << 22));
  EXPECT_THROW(pin19_code(f, Constants::minimax), std::invalid_argument);  // 41/256 needs 8 bits
}

// ROM 5's output must hold log2 of everything multiplexer 3 can carry: down to the
// smallest register-9 code (2^-frac) and log2 0 := −cos_frac_bits, up to the largest.
TEST(FormatWidths, Log2FormatHoldsTheWholeRangeOfRom5) {
  for (int frac : {16, 22, 30, 40}) {
    for (int ints : {3, 14, 20}) {
      Widths w;
      w.reg9_frac_bits = frac;
      w.reg9_int_bits = ints;
      if (ints + frac > 62) continue;
      const Formats f(w);
      const double lowest = -std::max(frac, w.cos_frac_bits);
      const double highest = ints;  // log2 of a value just below 2^ints
      EXPECT_LE(f.log2.to_real(f.log2.min_code()), lowest) << f.reg9.name();
      EXPECT_GE(f.log2.to_real(f.log2.max_code()), highest - f.log2.lsb()) << f.reg9.name();
    }
  }
}

TEST(FormatWidths, Rom38FormatHoldsTheEnergyPolicyAtN1000) {
  const Formats f;
  EXPECT_GT(f.rom38.to_real(f.rom38.max_code()), 1002.0 / (2.0 * M_PI));
}

TEST(FormatWidths, ValidateNamesTheWidthTheValueAndTheRange) {
  Widths w;
  EXPECT_NO_THROW(w.validate());

  w = Widths{};
  w.n_bits = 9;  // cannot hold n = 1000
  EXPECT_TRUE(refused_naming(w, "n_bits", "9", "[10, 16]"));

  w = Widths{};
  w.cos_frac_bits = 0;
  EXPECT_TRUE(refused_naming(w, "cos_frac_bits", "0", "allowed range"));

  w = Widths{};
  w.rgb_bits = 0;
  EXPECT_TRUE(refused_naming(w, "rgb_bits", "0", "allowed range"));

  w = Widths{};
  w.rom5_addr_bits = 40;
  EXPECT_TRUE(refused_naming(w, "rom5_addr_bits", "40", "allowed range"));

  w = Widths{};
  w.rom5_word_bits = -3;
  EXPECT_TRUE(refused_naming(w, "rom5_word_bits", "-3", "allowed range"));

  // Multiplexer 3 aligns cos λ to register 9's format: register 9 needs at least as
  // many fraction bits as cos λ; the range names that bound.
  w = Widths{};
  w.reg9_frac_bits = 15;
  EXPECT_TRUE(refused_naming(w, "reg9_frac_bits", "15", "[16, "));

  w = Widths{};
  w.out_frac_bits = 21;  // more than the norm bus provides
  EXPECT_TRUE(refused_naming(w, "out_frac_bits", "21", "[0, 20]"));
}

TEST(FormatWidths, ABusWiderThanACodeIsRefused) {
  Widths w;
  w.reg9_int_bits = 20;
  w.reg9_frac_bits = 40;
  w.norm_frac_bits = 30;
  w.norm_int_bits = 20;
  w.out_int_bits = 40;
  w.out_frac_bits = 30;
  try {
    w.validate();
    FAIL() << "a 71-bit output bus was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("63 bits"), std::string::npos) << e.what();
  }
}

TEST(FormatWidths, FormatsRefuseBadWidths) {
  Widths w;
  w.n_bits = 4;
  EXPECT_THROW(Formats{w}, std::invalid_argument);
}

}  // namespace
}  // namespace specular
