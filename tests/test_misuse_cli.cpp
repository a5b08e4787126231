// Misuse of specular_tb's command line and files (docs/misuse.md, "Command line and files"): each row of
// the table as a user meets it — a subprocess, its exit status, its message, and the
// files it leaves. Every refusal exits 2 before anything runs, names the bad value and
// the allowed range, prints nothing on standard output and leaves no output file.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/subprocess.h"
#include "support/scratch.h"

namespace fs = std::filesystem;

namespace {

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";

using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::slurp;

fs::path scratch(const std::string& name) {
  return specular::testing_support::scratch_subdir(name);
}

/// Runs specular_tb with `arguments` (shell words) in `dir`; stdout/stderr are kept
/// outside `dir` so that `dir` shows only what the run left.
Outcome run_tb(const std::string& arguments, const fs::path& dir) {
  const fs::path logs = scratch("logs_" + dir.filename().string());
  const Outcome r = run_command("cd '" + dir.string() + "' && '" + tb + "' " + arguments, logs);
  fs::remove_all(logs);
  return r;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

/// A refused run: exit 2, every `expected` piece in the message, stdout empty, and
/// nothing in `dir` but `left` (the inputs the test put there).
void expect_refused(const std::string& arguments, const std::vector<std::string>& expected,
                    const fs::path& dir, std::vector<std::string> left = {}) {
  SCOPED_TRACE("specular_tb " + arguments);
  const Outcome r = run_tb(arguments, dir);
  EXPECT_FALSE(r.signalled) << "crashed";
  EXPECT_EQ(r.status, 2) << r.err;
  for (const std::string& piece : expected)
    EXPECT_NE(r.err.find(piece), std::string::npos) << "'" << piece << "' missing in: " << r.err;
  EXPECT_NE(r.err.find("specular_tb: error: "), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  std::sort(left.begin(), left.end());
  EXPECT_EQ(files_in(dir), left) << "no output, VCD or temporary file is left";
}

/// Output options that would leave files if the run went ahead.
const std::string outputs = " --format json --output out.json --vcd wave.vcd";

TEST(MisuseCli, ExponentOutsideOneToThousand) {
  const fs::path dir = scratch("n");
  expect_refused("--cos 0.5 --n 0" + outputs, {"n = 0", "[1, 1000]"}, dir);
  expect_refused("--cos 0.5 --n 1001" + outputs, {"n = 1001", "[1, 1000]"}, dir);
  expect_refused("--cos 0.5 --n -7" + outputs, {"n = -7", "[1, 1000]"}, dir);
}

TEST(MisuseCli, CosNegativeAboveOneOrNotANumber) {
  const fs::path dir = scratch("cos");
  expect_refused("--cos -0.1 --n 3" + outputs, {"-0.1", "[0, 1]"}, dir);
  expect_refused("--cos 1.0001 --n 3" + outputs, {"1.0001", "[0, 1]"}, dir);
  expect_refused("--cos nan --n 3" + outputs, {"nan", "[0, 1]"}, dir);
  expect_refused("--cos -inf --n 3" + outputs, {"inf", "[0, 1]"}, dir);
}

TEST(MisuseCli, RgbOutOfRange) {
  const fs::path dir = scratch("rgb");
  expect_refused("--cos 0.5 --n 3 --rgb 0,256,0" + outputs, {"G", "256", "[0, 255]"}, dir);
  expect_refused("--cos 0.5 --n 3 --rgb -1,0,0" + outputs, {"R", "-1", "[0, 255]"}, dir);
  expect_refused("--cos 0.5 --n 3 --rgb 1,2" + outputs, {"expected 3", "[0, 255]"}, dir);
}

TEST(MisuseCli, NonNumbers) {
  const fs::path dir = scratch("text");
  expect_refused("--cos half --n 3" + outputs, {"'half'", "not a number", "[0, 1]"}, dir);
  expect_refused("--cos 0.5 --n 3x" + outputs, {"'3x'", "not an integer", "[1, 1000]"}, dir);
  expect_refused("--cos 0.5 --n 3 --rgb 1,two,3" + outputs, {"'two'", "[0, 255]"}, dir);
  expect_refused("--cos '0.5 ' --n 3" + outputs, {"[0, 1]"}, dir);  // trailing blank
  expect_refused("--random many" + outputs, {"'many'", "[1, 100000000]"}, dir);
}

TEST(MisuseCli, EmptyAndTruncatedCsvLines) {
  const fs::path dir = scratch("csv");
  std::ofstream(dir / "empty_fields.csv") << "0.5,3,1,2,3\n,,,,\n";
  expect_refused("--input empty_fields.csv" + outputs, {"empty_fields.csv:2", "''", "[0, 1]"}, dir,
                 {"empty_fields.csv"});
  std::ofstream(dir / "truncated.csv") << "0.5,3,1,2,3\n0.25,40,1";  // cut mid-line, no newline
  expect_refused("--input truncated.csv" + outputs, {"truncated.csv:2", "expected 5 fields", "found 3"},
                 dir, {"empty_fields.csv", "truncated.csv"});
  std::ofstream(dir / "cut_field.csv") << "0.5,3,1,2,3\n0.25,40,1,2,";  // last field cut
  expect_refused("--input cut_field.csv" + outputs, {"cut_field.csv:2", "B = ''", "[0, 255]"}, dir,
                 {"cut_field.csv", "empty_fields.csv", "truncated.csv"});
  std::ofstream(dir / "nothing.csv") << "\n\n# no operations\n";
  expect_refused("--input nothing.csv" + outputs, {"nothing.csv", "no operations"}, dir,
                 {"cut_field.csv", "empty_fields.csv", "nothing.csv", "truncated.csv"});
}

TEST(MisuseCli, UnknownOptionsAndMissingValues) {
  const fs::path dir = scratch("options");
  expect_refused("--cos 0.5 --n 3 --colour red" + outputs, {"unknown option", "--colour"}, dir);
  expect_refused("-x" + outputs, {"unknown option", "'-x'"}, dir);
  expect_refused("--cos 0.5 --n" , {"--n", "needs a value", "[1, 1000]"}, dir);
}

TEST(MisuseCli, MissingAndUnreadableInputFiles) {
  const fs::path dir = scratch("unreadable");
  expect_refused("--input no_such.csv" + outputs, {"no_such.csv", "No such file"}, dir);
  expect_refused("--input ." + outputs, {"'.'", "directory"}, dir);
  // A file whose reads fail (EIO): /proc/self/mem at offset 0 is never mapped.
  expect_refused("--input /proc/self/mem" + outputs, {"/proc/self/mem", "read error"}, dir);
  if (geteuid() != 0) {  // root reads a mode-000 file anyway
    std::ofstream(dir / "locked.csv") << "0.5,3,1,2,3\n";
    fs::permissions(dir / "locked.csv", fs::perms::none);
    expect_refused("--input locked.csv" + outputs, {"locked.csv", "Permission denied"}, dir,
                   {"locked.csv"});
  }
}

TEST(MisuseCli, UnwritableOutputPathLeavesNothing) {
  const fs::path dir = scratch("output");
  expect_refused("--cos 0.5 --n 3 --output missing/out.csv", {"missing/out.csv", "No such file"}, dir);
  expect_refused("--cos 0.5 --n 3 --vcd missing/wave.vcd", {"missing/wave.vcd", "No such file"}, dir);
  fs::create_directory(dir / "sub");
  expect_refused("--cos 0.5 --n 3 --output sub", {"'sub'", "directory"}, dir, {"sub"});
  if (geteuid() != 0) {  // root writes into a read-only directory anyway
    fs::permissions(dir / "sub", fs::perms::owner_read | fs::perms::owner_exec);
    expect_refused("--cos 0.5 --n 3 --output sub/out.csv", {"sub/out.csv", "Permission denied"},
                   dir, {"sub"});
    fs::permissions(dir / "sub", fs::perms::owner_all);
  }
}

// Regression (issue 5 finding): the report used to be renamed over whatever the path
// named, so `--output /dev/full` as root replaced the device with a plain file. Only
// regular files are replaced now; devices and FIFOs are refused, links followed.
TEST(MisuseCli, OutputToAFifoIsRefusedAndTheFifoSurvives) {
  const fs::path dir = scratch("fifo");
  ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0600), 0);
  expect_refused("--cos 0.5 --n 3 --output pipe", {"'pipe'", "not a regular file"}, dir, {"pipe"});
  expect_refused("--cos 0.5 --n 3 --vcd pipe", {"'pipe'", "not a regular file"}, dir, {"pipe"});
  struct stat info {};
  ASSERT_EQ(lstat((dir / "pipe").c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode)) << "the FIFO is still a FIFO";

  fs::create_symlink("missing_target.csv", dir / "dangling");
  expect_refused("--cos 0.5 --n 3 --output dangling", {"'dangling'", "leads nowhere"}, dir,
                 {"dangling", "pipe"});
}

TEST(MisuseCli, OutputThroughASymlinkWritesTheFileItNames) {
  const fs::path dir = scratch("symlink");
  std::ofstream(dir / "report.csv") << "old\n";
  fs::create_symlink("report.csv", dir / "link.csv");
  const Outcome r = run_tb("--cos 0.5 --n 3 --model core --format csv --output link.csv", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv")) << "the link is kept";
  const std::string csv = slurp(dir / "report.csv");
  EXPECT_EQ(csv.rfind("cos,n,r,g,b,", 0), 0u) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2) << csv;
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"link.csv", "report.csv"}));
}

}  // namespace
