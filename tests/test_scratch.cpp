// The scratch-folder helper every test uses (tests/support/scratch.h, issue 12): a
// folder per test named after it inside one folder per process, fresh subfolders, the
// process's folder removed at exit after a pass and kept (and named) after a failure.
// The last two are seen from outside: this executable runs its own disabled tests
// with TEST_TMPDIR pointed at an empty folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/scratch.h"
#include "support/subprocess.h"

namespace fs = std::filesystem;
using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::scratch_dir;
using specular::testing_support::scratch_file;
using specular::testing_support::scratch_subdir;

namespace {

const std::string self = std::string(SPECULAR_BINARY_DIR) + "/tests/test_scratch";

std::vector<fs::path> entries(const fs::path& dir) {
  std::vector<fs::path> all;
  for (const auto& e : fs::directory_iterator(dir)) all.push_back(e.path());
  return all;
}

/// Runs one of this file's disabled tests in a child process whose scratch folders go
/// to `base`. LeakSanitizer is off in the child: it runs without the suite's suppressions.
Outcome run_disabled(const std::string& test, const fs::path& base, const fs::path& logs) {
  return run_command("TEST_TMPDIR='" + base.string() + "' ASAN_OPTIONS=detect_leaks=0 '" + self +
                         "' --gtest_also_run_disabled_tests --gtest_filter=Scratch." + test,
                     logs);
}

}  // namespace

TEST(Scratch, FolderIsTheTestsOwnNamedAfterItInsideTheProcessFolder) {
  const fs::path dir = scratch_dir();
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_EQ(dir.filename(), "Scratch.FolderIsTheTestsOwnNamedAfterItInsideTheProcessFolder");
  const std::string process = dir.parent_path().filename().string();
  const std::string prefix = "specular-test_" + std::to_string(::getpid()) + "_";
  EXPECT_EQ(process.rfind(prefix, 0), 0u) << process;
  EXPECT_EQ(process.size(), prefix.size() + 16) << "16 hex digits of randomness: " << process;
  EXPECT_EQ(scratch_dir(), dir) << "the same folder on every call within a test";
  EXPECT_EQ(scratch_file("a.csv"), dir / "a.csv");
  EXPECT_FALSE(fs::exists(scratch_file("a.csv"))) << "a path, not a file";
}

TEST(Scratch, SubdirIsFreshAndEmptyOnEveryCall) {
  const fs::path dir = scratch_subdir("run");
  EXPECT_EQ(dir, scratch_dir() / "run");
  EXPECT_TRUE(entries(dir).empty());
  std::ofstream(dir / "left.txt") << "x";
  ASSERT_EQ(entries(dir).size(), 1u);
  EXPECT_TRUE(entries(scratch_subdir("run")).empty()) << "emptied when asked for again";
}

// The two children of the next test: each leaves a file in its scratch folder.
TEST(Scratch, DISABLED_LeavesAFileThenPasses) { std::ofstream(scratch_file("evidence.txt")) << "pass\n"; }
TEST(Scratch, DISABLED_LeavesAFileThenFails) {
  std::ofstream(scratch_file("evidence.txt")) << "fail\n";
  ADD_FAILURE() << "failing on purpose: the folder must be kept";
}

TEST(Scratch, ProcessFolderIsRemovedAfterAPassAndKeptAfterAFailure) {
  ASSERT_TRUE(fs::exists(self)) << self;
  const fs::path logs = scratch_subdir("logs");

  const fs::path pass_base = scratch_subdir("pass_base");
  const Outcome passed = run_disabled("DISABLED_LeavesAFileThenPasses", pass_base, logs);
  EXPECT_EQ(passed.status, 0) << passed.out << passed.err;
  EXPECT_TRUE(entries(pass_base).empty()) << "nothing left after a pass";
  EXPECT_EQ(passed.err.find("scratch folder kept"), std::string::npos) << passed.err;

  const fs::path fail_base = scratch_subdir("fail_base");
  const Outcome failed = run_disabled("DISABLED_LeavesAFileThenFails", fail_base, logs);
  EXPECT_EQ(failed.status, 1) << failed.out << failed.err;
  const std::vector<fs::path> kept = entries(fail_base);
  ASSERT_EQ(kept.size(), 1u) << "the failed process's folder is kept";
  const fs::path evidence = kept.front() / "Scratch.DISABLED_LeavesAFileThenFails" / "evidence.txt";
  EXPECT_EQ(specular::testing_support::slurp(evidence), "fail\n");
  EXPECT_NE(failed.err.find("scratch folder kept (a test failed): " + kept.front().string()),
            std::string::npos)
      << failed.err;
}
