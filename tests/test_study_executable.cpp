// specular_study as a user runs it: a quick run writes every CSV file with its
// header, names its stages on stderr (no progress line: stderr is a file), and bad command lines are refused. The plotting
// script draws every picture from that run when Debian's python has matplotlib.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/subprocess.h"

namespace fs = std::filesystem;

namespace {

const std::string study = SPECULAR_STUDY_EXE;

using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::slurp;

/// A fresh, empty directory for one test, in its own scratch folder (support/scratch.h).
struct Scratch {
  explicit Scratch(const std::string& name) : path(specular::testing_support::scratch_subdir(name)) {}
  const fs::path path;
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  return cells;
}

// The header each file must carry (what scripts/flows/design_space/plot_study.py reads).
const std::map<std::string, std::string> expected_headers = {
    {"error_curves.csv",
     "n,lambda_deg,cos,exact,device_clamp,device_literal,formula_clamp,formula_literal,schlick,"
     "us5739820,device_minimax_half,device_minimax,device_clamp_err,device_literal_err,"
     "formula_clamp_err,formula_literal_err,schlick_err,us5739820_err,device_minimax_half_err,"
     "device_minimax_err"},
    {"max_error_by_n.csv",
     "n,zero_cos_formula,zero_cos_device,device_clamp_max_err,device_clamp_at_cos,"
     "device_literal_max_err,device_literal_at_cos,formula_clamp_max_err,formula_clamp_at_cos,"
     "formula_literal_max_err,formula_literal_at_cos,schlick_max_err,schlick_at_cos,"
     "us5739820_max_err,us5739820_at_cos,device_minimax_half_max_err,device_minimax_half_at_cos,"
     "device_minimax_max_err,device_minimax_at_cos,device_vs_formula_clamp_max,"
     "device_vs_formula_clamp_at_cos,device_vs_formula_literal_max,"
     "device_vs_formula_literal_at_cos"},
    {"energy_integrals.csv",
     "n,policy,k,exact_closed_form,exact,formula_clamp,formula_literal,schlick,us5739820,"
     "device_clamp,device_literal"},
    {"energy_device_energy.csv", "n,constants,rom38_word,device_energy,energy"},
    {"constants_search.csv",
     "search,F,extra_mul6_bits,h_code,h,a_code,a,s,max_error,error_above,error_below,boxes,"
     "evaluations"},
    {"widths.csv",
     "sweep,rom5_addr_bits,rom5_word_bits,reg9_frac_bits,rom38_frac_bits,is_default,rom5_words,"
     "rom5_bits,rom38_bits,max_err_vs_formula,worst_n,worst_cos,max_err_vs_exact,max_norm_err"},
    {"widths_near_one.csv", "rom5_addr_bits,n,cos_code,cos,device,formula,exact"},
    {"sphere_n1.csv",
     "x,y,size,n,cos,n_dot_l,exact,exact_energy,device_none,device_patent,device_energy,"
     "schlick,us5739820,device_minimax_half,device_minimax,device_minimax_device_energy"},
    {"sphere_n10.csv",
     "x,y,size,n,cos,n_dot_l,exact,exact_energy,device_none,device_patent,device_energy,"
     "schlick,us5739820,device_minimax_half,device_minimax,device_minimax_device_energy"},
    {"sphere_n100.csv",
     "x,y,size,n,cos,n_dot_l,exact,exact_energy,device_none,device_patent,device_energy,"
     "schlick,us5739820,device_minimax_half,device_minimax,device_minimax_device_energy"},
    {"sphere_n1000.csv",
     "x,y,size,n,cos,n_dot_l,exact,exact_energy,device_none,device_patent,device_energy,"
     "schlick,us5739820,device_minimax_half,device_minimax,device_minimax_device_energy"},
};
const std::vector<std::string> heatmaps = {"heatmap_device_clamp.csv", "heatmap_schlick.csv",
                                           "heatmap_us5739820.csv",
                                           "heatmap_device_vs_formula.csv"};

/// Runs the quick study once per process into `dir`; returns its outcome.
Outcome quick_run(const fs::path& dir) {
  return run_command("'" + study + "' --quick --workers 2 --out '" + (dir / "out").string() + "'", dir);
}

}  // namespace

TEST(StudyExecutable, QuickRunWritesEveryCsvWithItsHeader) {
  const Scratch scratch("quick");
  const fs::path& dir = scratch.path;
  const Outcome r = quick_run(dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path out = dir / "out";
  for (const auto& [name, header] : expected_headers) {
    std::ifstream in(out / name);
    ASSERT_TRUE(in) << name << " missing";
    std::string first, row;
    std::getline(in, first);
    EXPECT_EQ(first, header) << name;
    std::size_t rows = 0;
    while (std::getline(in, row)) {
      ++rows;
      ASSERT_EQ(split(row).size(), split(header).size()) << name << ": " << row;
    }
    EXPECT_GT(rows, 0u) << name;
  }
  for (const std::string& name : heatmaps) {
    std::ifstream in(out / name);
    ASSERT_TRUE(in) << name << " missing";
    std::string first, row;
    std::getline(in, first);
    EXPECT_EQ(first.rfind("n,0.1,", 0), 0u) << name << ": " << first;  // λ from 0.1°
    std::set<std::string> ns;
    while (std::getline(in, row)) ns.insert(split(row).front());
    EXPECT_EQ(ns, (std::set<std::string>{"1", "10", "100", "1000"})) << name;
  }
  EXPECT_TRUE(fs::exists(out / "summary.txt"));
  // Each stage named on stderr with its time, the summary on stdout; no progress line,
  // standard error being a file here (issue 27: specular_tb's rule, progress.h).
  EXPECT_NE(r.err.find("error study"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("width exploration"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("error study (all methods, every cos code): done in "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('%'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("Hemisphere integral"), std::string::npos) << r.out;
}

TEST(StudyExecutable, QuickRunIntegralsMatchClosedForms) {
  const Scratch scratch("integrals");
  const fs::path& dir = scratch.path;
  ASSERT_EQ(quick_run(dir).status, 0);
  std::ifstream in(dir / "out" / "energy_integrals.csv");
  std::string line;
  std::getline(in, line);
  int rows = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> c = split(line);
    const double n = std::stod(c[0]), exact = std::stod(c[4]);
    const double lobe = 2 * 3.14159265358979323846 / (n + 2);
    const double expected = c[1] == "energy" ? 1.0 : c[1] == "patent" ? lobe * lobe : lobe;
    EXPECT_NEAR(exact, expected, 1e-8 * std::max(1.0, expected)) << line;  // 10 digits in CSV
    ++rows;
  }
  EXPECT_EQ(rows, 12);
}

TEST(StudyExecutable, BadCommandLinesAreRefused) {
  const Scratch scratch("bad");
  const fs::path& dir = scratch.path;
  const Outcome zero = run_command("'" + study + "' --workers 0", dir);
  EXPECT_EQ(zero.status, 2);
  EXPECT_NE(zero.err.find("--workers: 0 is outside the allowed range [1, 64]"), std::string::npos)
      << zero.err;
  const Outcome word = run_command("'" + study + "' --workers two", dir);
  EXPECT_EQ(word.status, 2);
  EXPECT_NE(word.err.find("--workers: 'two' is not an integer; allowed range [1, 64]"), std::string::npos) << word.err;
  const Outcome unknown = run_command("'" + study + "' --fast", dir);
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("unknown option '--fast'"), std::string::npos) << unknown.err;
  const Outcome missing = run_command("'" + study + "' --out", dir);
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--out needs a value"), std::string::npos) << missing.err;
  // An output directory that cannot be created (its parent is a file).
  std::ofstream(dir / "a_file") << "x";
  const Outcome blocked = run_command("'" + study + "' --quick --out '" + (dir / "a_file" / "sub").string() + "'", dir);
  EXPECT_EQ(blocked.status, 1);
  EXPECT_NE(blocked.err.find("cannot create directory"), std::string::npos) << blocked.err;
}

TEST(StudyExecutable, PlotScriptDrawsEveryPicture) {
  const std::string python = "/usr/bin/python3";
  if (std::system((python + " -c 'import numpy, matplotlib' 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << python << " without numpy/matplotlib (scripts/setup.sh installs them)";
  const Scratch scratch("plot");
  const fs::path& dir = scratch.path;
  ASSERT_EQ(quick_run(dir).status, 0);
  const Outcome r = run_command(python + " '" + std::string(SPECULAR_SOURCE_DIR) +
                            "/scripts/flows/design_space/plot_study.py' '" + (dir / "out").string() + "' '" +
                            (dir / "png").string() + "'",
                        dir);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* name : {"error_curves.png", "lobes.png", "max_error_by_n.png",
                           "energy_integrals.png", "energy_policy.png", "heatmap_error.png",
                           "spheres.png", "widths.png", "constants.png"}) {
    const fs::path png = dir / "png" / name;
    ASSERT_TRUE(fs::exists(png)) << name;
    std::ifstream in(png, std::ios::binary);
    char magic[8] = {};
    in.read(magic, 8);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG") << name;
  }
  // A missing study directory is named.
  const Outcome missing =
      run_command(python + " '" + std::string(SPECULAR_SOURCE_DIR) + "/scripts/flows/design_space/plot_study.py' '" +
              (dir / "nothing").string() + "' '" + (dir / "png").string() + "'",
          dir);
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("nothing"), std::string::npos) << missing.err;
}
