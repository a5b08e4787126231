// Every test's scratch space is its own (issue 12): ctest runs tests in parallel, in
// random order and beside another build's run, so no test may build a temporary path
// by hand or use a fixed file name in a shared folder.
//
// How to use it in a new test (this header is all there is):
//
//   #include "support/scratch.h"
//   using specular::testing_support::scratch_file;
//   using specular::testing_support::scratch_subdir;
//
//   const std::filesystem::path csv = scratch_file("input.csv");  // any name: the folder is yours
//   const std::filesystem::path dir = scratch_subdir("run");     // a fresh, empty folder
//
// The process's folder is <base>/specular-test_<pid>_<random>, <base> being
// $TEST_TMPDIR, else $TMPDIR, else GoogleTest's TempDir() (/tmp/), created with
// create_directory (never reused: another process's folder is never touched), and
// inside it one folder per test, named after the test (Suite.Name, '/' as '_').
// Files a test's subprocesses write there go with it. At exit the whole folder is
// removed; when a test failed it is kept and its path printed on stderr, so that
// `ctest --output-on-failure` shows where the evidence is.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

namespace specular {
namespace testing_support {

namespace scratch_detail {

/// A name safe in a path: letters, digits, '.', '-', '_'; anything else becomes '_'.
inline std::string path_safe(const std::string& text) {
  std::string safe = text.substr(0, 120);
  for (char& c : safe)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '_';
  return safe;
}

/// Where the process's folder goes: $TEST_TMPDIR, $TMPDIR, or GoogleTest's TempDir().
inline std::filesystem::path base_folder() {
  for (const char* variable : {"TEST_TMPDIR", "TMPDIR"}) {
    const char* value = std::getenv(variable);
    if (value != nullptr && value[0] != '\0') return value;
  }
  return ::testing::TempDir();
}

/// The process's folder: made on first use, removed at exit unless a test failed.
class ProcessFolder {
 public:
  ProcessFolder() {
    const std::filesystem::path base = base_folder();
    std::random_device entropy;
    std::mt19937_64 draw((static_cast<std::uint64_t>(entropy()) << 32) ^ entropy() ^
                         static_cast<std::uint64_t>(::getpid()));
    for (int attempt = 0; attempt < 100; ++attempt) {
      char suffix[17];
      std::snprintf(suffix, sizeof suffix, "%016llx", static_cast<unsigned long long>(draw()));
      const std::filesystem::path candidate =
          base / ("specular-test_" + std::to_string(::getpid()) + "_" + suffix);
      std::error_code error;
      // create_directory is false when the name exists: only a folder made here is ours.
      if (std::filesystem::create_directory(candidate, error)) {
        path_ = candidate;
        return;
      }
      if (error) throw std::runtime_error("scratch: cannot create " + candidate.string() + ": " + error.message());
    }
    throw std::runtime_error("scratch: no free name under " + base.string());
  }
  ~ProcessFolder() {
    const ::testing::UnitTest* unit = ::testing::UnitTest::GetInstance();
    if (unit != nullptr && unit->Failed()) {
      std::fprintf(stderr, "scratch folder kept (a test failed): %s\n", path_.c_str());
      return;
    }
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ProcessFolder(const ProcessFolder&) = delete;
  ProcessFolder& operator=(const ProcessFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace scratch_detail

/// The running test's own folder (created on first use): the process's folder /
/// Suite.Name. Outside a test (static set-up) it is the process's folder / "process".
inline std::filesystem::path scratch_dir() {
  static const scratch_detail::ProcessFolder process;  // destroyed at exit: removes it
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name =
      test == nullptr ? "process" : std::string(test->test_suite_name()) + "." + test->name();
  const std::filesystem::path dir = process.path() / scratch_detail::path_safe(name);
  std::filesystem::create_directories(dir);
  return dir;
}

/// A path for file `name` in the test's folder (the file is not created).
inline std::filesystem::path scratch_file(const std::string& name) { return scratch_dir() / name; }

/// A fresh, empty folder `name` in the test's folder (emptied if it was used before).
inline std::filesystem::path scratch_subdir(const std::string& name) {
  const std::filesystem::path dir = scratch_dir() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace testing_support
}  // namespace specular
