// specular_tb's command line: every good form, and every bad one gets a UsageError
// whose message names the bad value and what is allowed.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "options.h"
#include "usage_error.h"

using specular::Normalisation;
using specular::Saturation;
using namespace specular::tb;

namespace {

Options parse(std::vector<std::string> args) { return parse_options(args); }

/// The message of the UsageError that parsing `args` throws ("" if none is thrown).
std::string error_of(std::vector<std::string> args) {
  try {
    parse_options(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

void expect_error(std::vector<std::string> args, std::vector<std::string> fragments) {
  const std::string message = error_of(args);
  ASSERT_FALSE(message.empty()) << "no error for: " << testing::PrintToString(args);
  for (const std::string& f : fragments)
    EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' missing in: " << message;
}

}  // namespace

TEST(CliOptions, OnePointWithDefaults) {
  const Options o = parse({"--cos", "0.5", "--n", "10", "--rgb", "1,2,3"});
  EXPECT_EQ(o.stimulus, StimulusKind::point);
  EXPECT_DOUBLE_EQ(o.cos, 0.5);
  EXPECT_EQ(o.n, 10);
  EXPECT_EQ(o.rgb, (std::array<long long, 3>{1, 2, 3}));
  EXPECT_EQ(o.model, Model::pin);
  EXPECT_EQ(o.config.normalisation, Normalisation::patent);
  EXPECT_EQ(o.config.saturation, Saturation::clamp);
  EXPECT_EQ(o.format, OutputFormat::text);
  EXPECT_EQ(o.clock_period_ps, 10000u);
  EXPECT_TRUE(o.output_path.empty());
  EXPECT_TRUE(o.vcd_path.empty());
}

TEST(CliOptions, RgbDefaultsToFullScale) {
  const Options o = parse({"--cos", "1", "--n", "1"});
  EXPECT_EQ(o.rgb, (std::array<long long, 3>{255, 255, 255}));
}

TEST(CliOptions, EveryOptionAndEqualsForm) {
  const Options o = parse({"--random=50", "--seed", "7", "--model=core", "--policy", "energy",
                           "--saturation", "literal", "--clock-period", "2.5ns", "--format",
                           "json", "--output", "out.json"});
  EXPECT_EQ(o.stimulus, StimulusKind::random);
  EXPECT_EQ(o.random_count, 50u);
  EXPECT_EQ(o.seed, 7u);
  EXPECT_EQ(o.model, Model::core);
  EXPECT_EQ(o.config.normalisation, Normalisation::energy);
  EXPECT_EQ(o.config.saturation, Saturation::literal);
  EXPECT_EQ(o.clock_period_ps, 2500u);
  EXPECT_EQ(o.format, OutputFormat::json);
  EXPECT_EQ(o.output_path, "out.json");
}

TEST(CliOptions, SweepInputAndVcd) {
  EXPECT_EQ(parse({"--sweep"}).stimulus, StimulusKind::sweep);
  EXPECT_EQ(parse({"--sweep", "--rgb", "9,9,9"}).rgb, (std::array<long long, 3>{9, 9, 9}));
  const Options o = parse({"--input", "vectors.csv", "--vcd", "x.vcd", "--policy", "none"});
  EXPECT_EQ(o.stimulus, StimulusKind::input);
  EXPECT_EQ(o.input_path, "vectors.csv");
  EXPECT_EQ(o.vcd_path, "x.vcd");
  EXPECT_FALSE(o.real_views) << "the *_real views are opt-in";
  EXPECT_EQ(o.config.normalisation, Normalisation::none);
  EXPECT_TRUE(parse({"--sweep", "--vcd", "x.vcd", "--real-views"}).real_views);
}

TEST(CliOptions, HelpNeedsNothingElse) {
  EXPECT_TRUE(parse({"--help"}).help);
  EXPECT_TRUE(parse({"-h"}).help);
  const std::string help = help_text();
  for (const char* option : {"--cos", "--n", "--rgb", "--input", "--sweep", "--random", "--seed",
                             "--model", "--policy", "--saturation", "--constants", "--clock-period", "--vcd",
                             "--real-views", "--format", "--output", "--help", "annotated latency"})
    EXPECT_NE(help.find(option), std::string::npos) << option;
}

TEST(CliOptions, NOutsideItsRange) {
  expect_error({"--cos", "0.5", "--n", "0"}, {"--n", "0", "[1, 1000]"});
  expect_error({"--cos", "0.5", "--n", "1001"}, {"--n", "1001", "[1, 1000]"});
  expect_error({"--cos", "0.5", "--n", "-3"}, {"--n", "-3", "[1, 1000]"});
  expect_error({"--cos", "0.5", "--n", "99999999999999999999"},
               {"99999999999999999999", "[1, 1000]"});
}

TEST(CliOptions, NNotAnInteger) {
  expect_error({"--cos", "0.5", "--n", "12abc"}, {"--n", "'12abc'", "not an integer", "[1, 1000]"});
  expect_error({"--cos", "0.5", "--n", "2.5"}, {"'2.5'", "[1, 1000]"});
  expect_error({"--cos", "0.5", "--n", ""}, {"--n", "[1, 1000]"});
}

TEST(CliOptions, CosOutsideItsRangeOrNotANumber) {
  expect_error({"--cos", "1.5", "--n", "3"}, {"--cos", "1.5", "[0, 1]"});
  expect_error({"--cos", "-0.25", "--n", "3"}, {"--cos", "-0.25", "[0, 1]"});
  expect_error({"--cos", "nan", "--n", "3"}, {"--cos", "nan", "[0, 1]"});
  expect_error({"--cos", "inf", "--n", "3"}, {"--cos", "inf", "[0, 1]"});
  expect_error({"--cos", "x", "--n", "3"}, {"--cos", "'x'", "not a number", "[0, 1]"});
  expect_error({"--cos", "0.5v", "--n", "3"}, {"'0.5v'", "[0, 1]"});
}

TEST(CliOptions, RgbOutsideItsFormatOrWrongCount) {
  expect_error({"--cos", "1", "--n", "1", "--rgb", "1,256,3"}, {"--rgb", "G", "256", "[0, 255]"});
  expect_error({"--cos", "1", "--n", "1", "--rgb", "-1,2,3"}, {"--rgb", "R", "-1", "[0, 255]"});
  expect_error({"--cos", "1", "--n", "1", "--rgb", "1,2"}, {"--rgb", "'1,2'", "2 value", "expected 3", "[0, 255]"});
  expect_error({"--cos", "1", "--n", "1", "--rgb", "1,2,3,4"}, {"4 value", "expected 3"});
  expect_error({"--cos", "1", "--n", "1", "--rgb", "1,z,3"}, {"G", "'z'", "[0, 255]"});
}

TEST(CliOptions, UnknownOptionsAndMissingValues) {
  expect_error({"--cos", "1", "--n", "1", "--colour", "red"}, {"unknown option", "--colour"});
  expect_error({"stray"}, {"unknown option", "stray"});
  expect_error({"--cos", "1", "--n"}, {"--n", "needs a value", "[1, 1000]"});
  expect_error({"--cos"}, {"--cos", "needs a value", "[0, 1]"});
  expect_error({"--sweep", "--output"}, {"--output", "needs a value"});
  expect_error({"--sweep=yes"}, {"--sweep", "no value"});
}

TEST(CliOptions, ChoicesNameTheAllowedValues) {
  expect_error({"--sweep", "--model", "gates"}, {"--model", "'gates'", "pin, core, tlm, rtl, rtl-sync"});
  expect_error({"--sweep", "--policy", "phong"},
               {"--policy", "'phong'", "patent, energy, none, device-energy"});
  expect_error({"--sweep", "--constants", "schlick"},
               {"--constants", "'schlick'", "patent, minimax-half, minimax"});
  expect_error({"--sweep", "--constants"}, {"--constants", "needs a value", "minimax-half"});
  expect_error({"--sweep", "--saturation", "wrap"}, {"--saturation", "'wrap'", "clamp, literal"});
  expect_error({"--sweep", "--format", "xml"}, {"--format", "'xml'", "text, csv, json"});
}

TEST(CliOptions, ClockPeriodIsAPositiveMultipleOfFourPicoseconds) {
  EXPECT_EQ(parse({"--sweep", "--clock-period", "1us"}).clock_period_ps, 1000000u);
  EXPECT_EQ(parse({"--sweep", "--clock-period", "4ps"}).clock_period_ps, 4u);
  EXPECT_EQ(parse({"--sweep", "--clock-period", "8000fs"}).clock_period_ps, 8u);
  EXPECT_EQ(parse({"--sweep", "--clock-period", "1 ms"}).clock_period_ps, 1000000000u);
  expect_error({"--sweep", "--clock-period", "10ps"}, {"--clock-period", "'10ps'", "multiple of 4 ps"});
  expect_error({"--sweep", "--clock-period", "0ns"}, {"'0ns'", "[4 ps, 1 ms]"});
  expect_error({"--sweep", "--clock-period", "2.0005ns"}, {"'2.0005ns'", "whole number of picoseconds"});
  expect_error({"--sweep", "--clock-period", "10"}, {"'10'", "no unit"});
  expect_error({"--sweep", "--clock-period", "10 hz"}, {"'10 hz'", "unknown unit"});
  expect_error({"--sweep", "--clock-period", "2ms"}, {"'2ms'", "[4 ps, 1 ms]"});
  expect_error({"--sweep", "--clock-period", "-10ns"}, {"'-10ns'", "not a time"});
  expect_error({"--sweep", "--clock-period", "99999999999999999999s"}, {"too"});
}

TEST(CliOptions, RandomCountAndSeed) {
  expect_error({"--random", "0"}, {"--random", "0", "[1, 100000000]"});
  expect_error({"--random", "ten"}, {"--random", "'ten'", "[1, 100000000]"});
  expect_error({"--random", "5", "--seed", "-1"}, {"--seed", "'-1'", "[0, 18446744073709551615]"});
  EXPECT_EQ(parse({"--random", "5", "--seed", "18446744073709551615"}).seed, 18446744073709551615u);
}

TEST(CliOptions, ExactlyOneStimulusSource) {
  expect_error({}, {"nothing to compute"});
  expect_error({"--model", "core"}, {"nothing to compute"});
  expect_error({"--sweep", "--random", "3"}, {"choose one of"});
  expect_error({"--cos", "1", "--n", "1", "--input", "f.csv"}, {"choose one of"});
  expect_error({"--cos", "1"}, {"--n"});
  expect_error({"--n", "4"}, {"--cos"});
  expect_error({"--input", "f.csv", "--rgb", "1,1,1"}, {"--rgb"});
  expect_error({"--sweep", "--seed", "3"}, {"--seed", "--random"});
}

TEST(CliOptions, RepeatedOptionsAndConflicts) {
  expect_error({"--cos", "1", "--n", "1", "--n", "2"}, {"--n", "more than once"});
  expect_error({"--sweep", "--model", "core", "--vcd", "x.vcd"}, {"--vcd", "--model pin"});
  expect_error({"--sweep", "--vcd", "a", "--output", "a"}, {"same file", "'a'"});
  expect_error({"--sweep", "--output", ""}, {"--output", "empty"});
  expect_error({"--sweep", "--real-views"}, {"--real-views", "needs --vcd"});
  expect_error({"--sweep", "--vcd", "x.vcd", "--real-views=yes"}, {"--real-views", "no value", "'yes'"});
  // The synchronous variant takes --vcd (Verilator's VCD), not the real-valued views.
  EXPECT_EQ(parse({"--sweep", "--model", "rtl-sync", "--vcd", "x.vcd"}).vcd_path, "x.vcd");
  expect_error({"--sweep", "--model", "rtl-sync", "--vcd", "x.vcd", "--real-views"},
               {"--real-views", "rtl-sync", "specular_rtl_sync.gtkw"});
}

// --width: one per width, repeatable; the RTL's w20 set; a bad name lists the names,
// a bad value names the range; --rgb is checked at the widths set.
TEST(CliOptions, WidthsOtherThanTheDefaults) {
  const Options o = parse({"--random", "3", "--width", "rom5_word_bits=20",
                           "--width=reg9_frac_bits=16"});
  EXPECT_EQ(o.config.widths.rom5_word_bits, 20);
  EXPECT_EQ(o.config.widths.reg9_frac_bits, 16);
  EXPECT_EQ(o.config.widths.cos_frac_bits, 16) << "the others keep docs/design.md's widths";
  EXPECT_EQ(parse({"--random", "3"}).config.widths.rom5_word_bits, 22);
  expect_error({"--random", "3", "--width", "rom5_bits=20"},
               {"--width", "'rom5_bits'", "rom5_word_bits", "out_frac_bits"});
  expect_error({"--random", "3", "--width", "reg9_frac_bits=8"},
               {"--width", "reg9_frac_bits = 8", "[16, 40]"});
  expect_error({"--random", "3", "--width", "reg9_frac_bits"}, {"--width", "NAME=VALUE"});
  expect_error({"--random", "3", "--width", "n_bits=ten"}, {"--width", "ten"});
  // R = 300 fits 9-bit intensities, not the default 8 bits.
  EXPECT_EQ(parse({"--cos", "1", "--n", "1", "--rgb", "300,0,0", "--width", "rgb_bits=9"}).rgb[0],
            300u);
  expect_error({"--cos", "1", "--n", "1", "--rgb", "300,0,0"}, {"--rgb", "300"});
}

// Issue 27: trace windows, failure traces, --quiet. Each error names the option, the
// value and what is allowed.
TEST(CliOptions, TraceWindowsAndFailureTraces) {
  const Options o = parse_options({"--random", "100", "--vcd", "w.vcd", "--trace-ops", "734511:2", "--quiet"});
  EXPECT_TRUE(o.trace_window);
  EXPECT_EQ(o.trace_first, 734511u);
  EXPECT_EQ(o.trace_count, 2u);
  EXPECT_TRUE(o.quiet);
  const Options f = parse_options({"--sweep", "--model", "pin", "--trace-failures", "fails",
                                   "--trace-failures-max", "3"});
  EXPECT_EQ(f.failure_dir, "fails");
  EXPECT_EQ(f.failure_max, 3u);
  EXPECT_EQ(parse_options({"--sweep", "--trace-failures", "d"}).failure_max, 10u);
  EXPECT_FALSE(parse_options({"--sweep"}).quiet);

  expect_error({"--sweep", "--vcd", "w.vcd", "--trace-ops", "12"}, {"--trace-ops", "'12'", "FIRST:COUNT"});
  expect_error({"--sweep", "--vcd", "w.vcd", "--trace-ops", "12:0"}, {"--trace-ops", "COUNT = 0", "[1, "});
  expect_error({"--sweep", "--vcd", "w.vcd", "--trace-ops", "x:3"}, {"--trace-ops", "FIRST", "'x'"});
  expect_error({"--sweep", "--vcd", "w.vcd", "--trace-ops", "-1:3"}, {"--trace-ops", "'-1'"});
  expect_error({"--sweep", "--trace-ops", "1:3"}, {"--trace-ops needs --vcd"});
  expect_error({"--sweep", "--model", "core", "--trace-failures", "d"},
               {"--trace-failures", "pin, rtl or rtl-sync", "core"});
  expect_error({"--sweep", "--trace-failures", "d", "--vcd", "w.vcd"}, {"--trace-failures", "--vcd"});
  expect_error({"--sweep", "--trace-failures", ""}, {"--trace-failures", "empty"});
  expect_error({"--sweep", "--trace-failures", "d", "--trace-failures-max", "0"},
               {"--trace-failures-max", "0", "[1, 1000]"});
  expect_error({"--sweep", "--trace-failures", "d", "--trace-failures-max", "1001"},
               {"--trace-failures-max", "1001", "[1, 1000]"});
  expect_error({"--sweep", "--trace-failures-max", "5"}, {"--trace-failures-max needs --trace-failures"});
  expect_error({"--sweep", "--quiet=yes"}, {"--quiet", "no value", "'yes'"});
}
