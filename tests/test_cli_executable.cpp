// specular_tb as a user runs it: a subprocess, its exit status, its files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "support/subprocess.h"
#include "support/scratch.h"

namespace fs = std::filesystem;

namespace {

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";

using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::slurp;

/// A fresh, empty scratch directory for one test.
fs::path scratch(const std::string& name) {
  return specular::testing_support::scratch_subdir(name);
}

/// Runs specular_tb with `arguments` (or, with `whole_command`, runs `arguments` as
/// the shell command itself); `dir` holds the captured output only while it runs.
Outcome run_tb(const std::string& arguments, const fs::path& dir, bool whole_command = false) {
  return run_command(whole_command ? arguments : "'" + tb + "' " + arguments, dir);
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  return names;
}

}  // namespace

TEST(CliExecutable, IsBuilt) { ASSERT_TRUE(fs::exists(tb)) << tb << " (build the whole tree)"; }

TEST(CliExecutable, GoodPointExitsZero) {
  const fs::path dir = scratch("good");
  const Outcome r = run_tb("--cos 0.9 --n 10 --rgb 200,100,50", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("PASS"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("measured on the pins"), std::string::npos) << r.out;
  // Nothing from the SystemC kernel on standard output.
  EXPECT_EQ(r.out.find("SystemC"), std::string::npos) << r.out;
}

TEST(CliExecutable, CsvOnStdoutIsPure) {
  const fs::path dir = scratch("csv");
  const Outcome r = run_tb("--cos 1 --n 1000 --format csv", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string header, row, extra;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header.rfind("cos,n,r,g,b,cos_q,approx,approx_ref,norm,", 0), 0u) << r.out;
  EXPECT_EQ(row.rfind("1,1000,255,255,255,1,", 0), 0u) << r.out;
  EXPECT_FALSE(std::getline(in, extra)) << "only header and one row: " << r.out;
  EXPECT_NE(r.err.find("PASS"), std::string::npos);
}

TEST(CliExecutable, BadNExitsTwoWithMessage) {
  const fs::path dir = scratch("bad_n");
  const Outcome r = run_tb("--cos 0.5 --n 0", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("n = 0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[1, 1000]"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(CliExecutable, BadConstantsAndPolicyExitTwoNamingTheChoices) {
  const fs::path dir = scratch("bad_constants");
  Outcome r = run_tb("--cos 0.5 --n 3 --constants minimax-full", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("'minimax-full' is not one of: patent, minimax-half, minimax"),
            std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  r = run_tb("--cos 0.5 --n 3 --policy device_energy", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("'device_energy' is not one of: patent, energy, none, device-energy"),
            std::string::npos) << r.err;
}

TEST(CliExecutable, ARefusedPolicyCombinationExitsTwoBeforeRunning) {
  const fs::path dir = scratch("refused_combination");
  const fs::path target = dir / "out.csv";
  const Outcome r = run_tb("--cos 0.5 --n 3 --policy device-energy --saturation literal --output '" +
                               target.string() + "'", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("saturation literal with normalisation device-energy and constants patent"),
            std::string::npos) << r.err;
  EXPECT_NE(r.err.find("use saturation clamp or other constants"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(target));
}

TEST(CliExecutable, ConstantsAndDeviceEnergyRunAndPass) {
  const fs::path dir = scratch("constants_run");
  // cos = 1: the device's peak s·A = 1, so under normalisation none with minimax
  // constants norm ≈ 1 while register 9 (approx) holds 1/s = 0.600873.
  const Outcome r = run_tb("--cos 1 --n 10 --rgb 255,255,255 --model core --policy none "
                           "--constants minimax --format csv", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(",0.6008"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("PASS"), std::string::npos) << r.err;
  const Outcome e = run_tb("--sweep --model core --policy device-energy --constants minimax-half", dir);
  EXPECT_EQ(e.status, 0) << e.err << e.out;
  EXPECT_NE(e.out.find("constants minimax-half"), std::string::npos) << e.out;
  // The report says what the columns mean under these constants.
  EXPECT_NE(e.out.find("pin 20 a = 1.148987293, pin 19 h = 0.500000000, ROM 38 scale s = 0.953465295"),
            std::string::npos) << e.out;
}

TEST(CliExecutable, NonNumberAndUnknownOptionExitTwo) {
  const fs::path dir = scratch("bad_text");
  Outcome r = run_tb("--cos 0.5 --n 12abc", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("'12abc'"), std::string::npos) << r.err;
  r = run_tb("--cos 0.5 --n 3 --frobnicate", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--frobnicate"), std::string::npos) << r.err;
}

// --config FILE (CLI11's, TOML or INI): every long option settable there; the command
// line wins; a bad value in it is named with the file's line and exits 2, nothing run.
TEST(CliExecutable, ConfigFileSetsOptionsAndItsBadValuesAreNamed) {
  const fs::path dir = scratch("config");
  const fs::path toml = dir / "run.toml";
  std::ofstream(toml) << "# one point through the core, as CSV\n"
                         "cos = 1\nn = 1000\nmodel = \"core\"\nformat = \"csv\"\nquiet = true\n";
  const Outcome from_file = run_tb("--config '" + toml.string() + "'", dir);
  const Outcome on_line = run_tb("--cos 1 --n 1000 --model core --format csv --quiet", dir);
  EXPECT_EQ(from_file.status, 0) << from_file.err;
  EXPECT_EQ(from_file.out, on_line.out);
  EXPECT_EQ(from_file.out.rfind("cos,n,r,g,b,", 0), 0u) << from_file.out;
  // The command line wins over the file: n = 10 replaces its 1000.
  const Outcome wins = run_tb("--config '" + toml.string() + "' --n 10", dir);
  EXPECT_EQ(wins.status, 0) << wins.err;
  EXPECT_NE(wins.out.find("\n1,10,255,255,255,"), std::string::npos) << wins.out;
  // INI, the same keys; a flag and a width.
  const fs::path ini = dir / "run.ini";
  std::ofstream(ini) << "; a random run at another width\nrandom=100\nmodel=core\nquiet=true\n"
                        "width=rom5_word_bits=20\n";
  const Outcome ini_run = run_tb("--config '" + ini.string() + "'", dir);
  const Outcome ini_line = run_tb("--random 100 --model core --quiet --width rom5_word_bits=20", dir);
  EXPECT_EQ(ini_run.status, 0) << ini_run.err;
  EXPECT_NE(ini_run.out.find("100 computation(s) from --random 100"), std::string::npos) << ini_run.out;
  EXPECT_EQ(ini_run.out.substr(0, ini_run.out.find("run time")), ini_line.out.substr(0, ini_line.out.find("run time")));
  // A bad value on line 3: the file, the line, the option, the value and the range.
  const fs::path bad = dir / "bad.toml";
  std::ofstream(bad) << "cos = 0.5\nmodel = \"core\"\nn = 1001\n";
  const Outcome refused = run_tb("--config '" + bad.string() + "'", dir);
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find(bad.string() + ":3: --n: n = 1001 is outside the allowed range [1, 1000]"),
            std::string::npos) << refused.err;
  EXPECT_TRUE(refused.out.empty()) << refused.out;
  // An unknown key and a missing file: exit 2, named.
  std::ofstream(dir / "unknown.toml") << "colour = \"red\"\n";
  const Outcome unknown = run_tb("--config '" + (dir / "unknown.toml").string() + "' --sweep", dir);
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("colour"), std::string::npos) << unknown.err;
  const Outcome missing = run_tb("--config '" + (dir / "none.toml").string() + "' --sweep", dir);
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("none.toml"), std::string::npos) << missing.err;
}

TEST(CliExecutable, UnwritableOutputExitsTwoAndLeavesNoFile) {
  const fs::path dir = scratch("unwritable");
  const fs::path target = dir / "missing_dir" / "out.csv";
  const Outcome r = run_tb("--cos 0.5 --n 3 --format csv --output '" + target.string() + "'", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(target.string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(target));
  EXPECT_TRUE(r.out.empty());
  // An output path that is a directory.
  const Outcome d = run_tb("--cos 0.5 --n 3 --output '" + dir.string() + "'", dir);
  EXPECT_EQ(d.status, 2);
  EXPECT_NE(d.err.find("directory"), std::string::npos) << d.err;
}

TEST(CliExecutable, BadInputFileLeavesNoOutputFile) {
  const fs::path dir = scratch("bad_input");
  std::ofstream(dir / "in.csv") << "0.5,3,1,2,3\n0.5,3,1,2\n";
  const fs::path target = dir / "out.json";
  const Outcome r = run_tb("--input '" + (dir / "in.csv").string() + "' --format json --output '" +
                        target.string() + "' --vcd '" + (dir / "w.vcd").string() + "'",
                    dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("in.csv:2"), std::string::npos) << r.err;
  EXPECT_EQ(files_in(dir), std::vector<std::string>{"in.csv"}) << "no output, VCD or temporary file";
}

TEST(CliExecutable, OutputFileIsWrittenWhole) {
  const fs::path dir = scratch("output");
  const fs::path target = dir / "out.csv";
  const Outcome r = run_tb("--random 20 --seed 5 --format csv --output '" + target.string() + "'", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string csv = slurp(target);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 21);
  EXPECT_EQ(files_in(dir), std::vector<std::string>{"out.csv"}) << "no temporary file left";
}

TEST(CliExecutable, VcdNamesScopesAfterThePatent) {
  for (const bool real_views : {false, true}) {
    SCOPED_TRACE(real_views ? "--real-views" : "codes only");
    const fs::path dir = scratch(real_views ? "vcd_real_views" : "vcd");
    const fs::path vcd = dir / "specular.vcd";
    const Outcome r = run_tb("--cos 0.9 --n 10 --vcd '" + vcd.string() + "'" +
                                 (real_views ? " --real-views" : ""),
                             dir);
    EXPECT_EQ(r.status, 0) << r.err;
    ASSERT_TRUE(fs::exists(vcd)) << r.err;
    const std::string text = slurp(vcd);
    for (const char* expected :
         {"$timescale", "$scope module tb $end", "$scope module dut $end",
          "$scope module cu16 $end", " q41 ", " q42 ", " select36 ", " write37 ", " pin35_done ",
          " pin27_start ", " pin28_clk ", " reg9_q ", " mul39_norm ", " pin24_r "})
      EXPECT_NE(text.find(expected), std::string::npos) << expected;
    for (const char* view : {" reg9_q_real ", " mul39_norm_real ", " pin24_r_real "})
      EXPECT_EQ(text.find(view) != std::string::npos, real_views) << view;
    EXPECT_EQ(text.find("signal_"), std::string::npos) << "every net has a patent name";
    EXPECT_EQ(files_in(dir), std::vector<std::string>{"specular.vcd"});
  }
}

namespace {

/// One bad request: the arguments, what the message must quote (the value as given
/// and the allowed range or choices), and the input files the scratch dir holds.
struct BadCase {
  const char* name;
  std::string arguments;
  std::vector<std::string> fragments;
  std::vector<std::pair<std::string, std::string>> files;  ///< name, content
};

std::vector<BadCase> bad_cases() {
  return {
      {"n_zero", "--cos 0.5 --n 0", {"n = 0", "[1, 1000]"}, {}},
      {"n_above", "--cos 0.5 --n 1001", {"n = 1001", "[1, 1000]"}, {}},
      {"n_negative", "--cos 0.5 --n -5", {"n = -5", "[1, 1000]"}, {}},
      {"n_huge", "--cos 0.5 --n 99999999999999999999", {"99999999999999999999", "[1, 1000]"}, {}},
      {"n_fraction", "--cos 0.5 --n 2.5", {"'2.5'", "not an integer", "[1, 1000]"}, {}},
      {"n_word", "--cos 0.5 --n ten", {"'ten'", "not an integer", "[1, 1000]"}, {}},
      {"cos_negative", "--cos -0.1 --n 3", {"cos = -0.1 ", "[0, 1]"}, {}},
      {"cos_above_one", "--cos 1.0001 --n 3", {"cos = 1.0001 ", "[0, 1]"}, {}},
      {"cos_nan", "--cos nan --n 3", {"cos = nan ", "[0, 1]"}, {}},
      {"cos_inf", "--cos inf --n 3", {"cos = inf ", "[0, 1]"}, {}},
      {"cos_overflow", "--cos 1e400 --n 3", {"cos = 1e400 ", "[0, 1]"}, {}},
      {"cos_word", "--cos abc --n 3", {"'abc'", "not a number", "[0, 1]"}, {}},
      {"cos_empty", "--cos '' --n 3", {"''", "not a number", "[0, 1]"}, {}},
      {"rgb_above", "--cos 1 --n 3 --rgb 1,256,3", {"G = 256", "[0, 255]"}, {}},
      {"rgb_negative", "--cos 1 --n 3 --rgb -1,2,3", {"R = -1", "[0, 255]"}, {}},
      {"rgb_word", "--cos 1 --n 3 --rgb 1,2,blue", {"'blue'", "[0, 255]"}, {}},
      {"rgb_count", "--cos 1 --n 3 --rgb 1,2", {"'1,2'", "expected 3", "[0, 255]"}, {}},
      {"unknown_option", "--cos 1 --n 3 --frobnicate", {"unknown option", "--frobnicate"}, {}},
      {"stray_word", "--cos 1 --n 3 extra", {"unknown option", "'extra'"}, {}},
      {"bad_policy", "--cos 1 --n 3 --policy phong", {"'phong'", "patent, energy, none"}, {}},
      {"bad_saturation", "--cos 1 --n 3 --saturation wrap", {"'wrap'", "clamp, literal"}, {}},
      {"bad_model", "--cos 1 --n 3 --model gates", {"'gates'", "pin, core, tlm, rtl, rtl-sync"}, {}},
      {"bad_format", "--cos 1 --n 3 --format xml", {"'xml'", "text, csv, json"}, {}},
      {"bad_clock", "--cos 1 --n 3 --clock-period 10ps", {"'10ps'", "multiple of 4 ps"}, {}},
      {"random_zero", "--random 0", {"N = 0", "[1, 100000000]"}, {}},
      {"missing_file", "--input absent.csv", {"absent.csv", "No such file"}, {}},
      {"directory_as_input", "--input sub", {"'sub'", "directory"}, {{"sub/keep.csv", "1,1,1,1,1\n"}}},
      {"empty_file", "--input in.csv", {"in.csv", "no operations"}, {{"in.csv", "# nothing\n\n"}}},
      {"file_cos", "--input in.csv", {"in.csv:3", "cos = 1.5 ", "[0, 1]"},
       {{"in.csv", "# header\n0.5,3,1,2,3\n1.5,3,1,2,3\n"}}},
      {"file_cos_nan", "--input in.csv", {"in.csv:1", "cos = NaN ", "[0, 1]"}, {{"in.csv", "NaN,3,1,2,3\n"}}},
      {"file_n", "--input in.csv", {"in.csv:2", "n = 1001", "[1, 1000]"},
       {{"in.csv", "0.5,3,1,2,3\n0.5,1001,1,2,3\n"}}},
      {"file_rgb", "--input in.csv", {"in.csv:1", "B = 300", "[0, 255]"}, {{"in.csv", "0.5,3,1,2,300\n"}}},
      {"file_text", "--input in.csv", {"in.csv:1", "'x'", "[1, 1000]"}, {{"in.csv", "0.5,x,1,2,3\n"}}},
      {"file_fields", "--input in.csv", {"in.csv:1", "expected 5 fields"}, {{"in.csv", "0.5,3,1,2\n"}}},
  };
}

/// Test names and failure messages show the case's name, not its bytes.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class CliBadInput : public ::testing::TestWithParam<BadCase> {};

}  // namespace

// Every kind of bad input through the executable, with --output and --vcd given: the
// message quotes the value and the allowed range, the exit status is 2 (not a
// signal), standard output stays empty, and no report, VCD or temporary file is left.
TEST_P(CliBadInput, NamesValueAndRangeExitsTwoLeavesNoFile) {
  const BadCase& c = GetParam();
  const fs::path dir = scratch(std::string("bad_") + c.name);
  std::vector<std::string> before;
  for (const auto& [name, content] : c.files) {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name) << content;
  }
  before = files_in(dir);
  std::sort(before.begin(), before.end());
  const Outcome r = run_tb("cd '" + dir.string() + "' && '" + tb + "' " + c.arguments +
                               " --output report.out --vcd wave.vcd",
                           dir, /*whole_command=*/true);
  EXPECT_EQ(r.status, 2) << r.err;
  for (const std::string& f : c.fragments)
    EXPECT_NE(r.err.find(f), std::string::npos) << "'" << f << "' missing in: " << r.err;
  EXPECT_NE(r.err.find("specular_tb: error: "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  std::vector<std::string> after = files_in(dir);
  std::sort(after.begin(), after.end());
  EXPECT_EQ(after, before) << "no report, VCD or temporary file left behind";
}

INSTANTIATE_TEST_SUITE_P(Cases, CliBadInput, ::testing::ValuesIn(bad_cases()),
                         [](const auto& info) { return std::string(info.param.name); });

// The options of one computation, end to end through the executable: another clock
// period (the latency stays 2.5 periods), another policy pair, each output format
// written to --output. Figures checked against the formula written out here.
TEST(CliExecutable, PolicyClockAndEveryFormatToAFile) {
  const fs::path dir = scratch("formats");
  // cos 0.25, n 1: x = log2 0.25 = −2, A = 1 − ½·log2 3 (positive: literal = clamp
  // here); energy K(1) = 3/(2π).
  const double a = 1 - 0.5 * std::log2(3.0);
  const double k = 3 / (2 * M_PI);
  for (const std::string format : {"text", "csv", "json"}) {
    SCOPED_TRACE(format);
    const fs::path target = dir / ("out." + format);
    const Outcome r = run_tb("--cos 0.25 --n 1 --rgb 255,0,16 --policy energy --saturation literal "
                             "--clock-period 2.5ns --format " + format + " --output '" +
                                 target.string() + "'",
                             dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.out.empty()) << "the report goes to --output only";
    const std::string report = slurp(target);
    if (format == "csv") {
      std::istringstream in(report);
      std::string header, row;
      std::getline(in, header);
      std::getline(in, row);
      std::vector<std::string> names, values;
      std::stringstream hs(header), rs(row);
      for (std::string f; std::getline(hs, f, ',');) names.push_back(f);
      for (std::string f; std::getline(rs, f, ',');) values.push_back(f);
      ASSERT_EQ(names.size(), values.size());
      std::map<std::string, std::string> field;
      for (std::size_t i = 0; i < names.size(); ++i) field[names[i]] = values[i];
      EXPECT_EQ(field["cos_q"], "0.25");
      EXPECT_NEAR(std::stod(field["approx_ref"]), a, 1e-15);
      EXPECT_NEAR(std::stod(field["approx"]), a, std::ldexp(1.0, -10));
      EXPECT_NEAR(std::stod(field["norm_ref"]), k * a, 1e-15);
      EXPECT_NEAR(std::stod(field["norm_exact"]), k * 0.25, 1e-15);
      EXPECT_NEAR(std::stod(field["out_r"]), k * a * 255, std::ldexp(1.0, -10) * 255 + std::ldexp(1.0, -13));
      EXPECT_EQ(field["out_g"], "0");
      EXPECT_EQ(field["cycles"], "2.5");
      EXPECT_EQ(field["reg1_hex"], "0x04000");  // 0.25 in U1.16, 17 bits
      EXPECT_EQ(field["pass"], "1");
    } else if (format == "json") {
      const nlohmann::json doc = nlohmann::json::parse(report);  // issue 25: nlohmann-json
      EXPECT_EQ(doc["settings"]["normalisation"], "energy") << report;
      EXPECT_EQ(doc["settings"]["saturation"], "literal");
      EXPECT_EQ(doc["settings"]["constants"], "patent");
      EXPECT_EQ(doc["settings"]["clock_period_ps"], 2500);
      EXPECT_EQ(doc["results"][0]["cycles"], 2.5);
      EXPECT_EQ(doc["results"][0]["reg1_hex"], "0x04000");
    } else {
      EXPECT_NE(report.find("normalisation energy, saturation literal, constants patent, clock 2500 ps"),
                std::string::npos)
          << report;
      EXPECT_NE(report.find("PASS"), std::string::npos);
    }
  }
  std::vector<std::string> files = files_in(dir);
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"out.csv", "out.json", "out.text"}));
}
