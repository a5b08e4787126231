// specular_tb as a user runs it: a subprocess, its exit status, its files.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";

struct Outcome {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh, empty scratch directory for one test.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("specular_tb_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Outcome run_tb(const std::string& arguments, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = "'" + tb + "' " + arguments + " >'" + out.string() + "' 2>'" +
                              err.string() + "' </dev/null";
  const int raw = std::system(command.c_str());
  Outcome r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
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

TEST(CliExecutable, NonNumberAndUnknownOptionExitTwo) {
  const fs::path dir = scratch("bad_text");
  Outcome r = run_tb("--cos 0.5 --n 12abc", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("'12abc'"), std::string::npos) << r.err;
  r = run_tb("--cos 0.5 --n 3 --frobnicate", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--frobnicate"), std::string::npos) << r.err;
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
  const fs::path dir = scratch("vcd");
  const fs::path vcd = dir / "specular.vcd";
  const Outcome r = run_tb("--cos 0.9 --n 10 --vcd '" + vcd.string() + "'", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(fs::exists(vcd)) << r.err;
  const std::string text = slurp(vcd);
  for (const char* expected :
       {"$timescale", "$scope module tb $end", "$scope module dut $end",
        "$scope module cu16 $end", " q41 ", " q42 ", " select36 ", " write37 ", " pin35_done ",
        " pin27_start ", " pin28_clk ", " reg9_q ", " reg9_q_real ", " mul39_norm_real ",
        " pin24_r_real "})
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  EXPECT_EQ(text.find("signal_"), std::string::npos) << "every net has a patent name";
  EXPECT_EQ(files_in(dir), std::vector<std::string>{"specular.vcd"});
}
