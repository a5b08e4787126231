// Running a program as a user does, for the tests that check an executable from the
// outside: its exit status, what it printed, and the files it left.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "scratch.h"

namespace specular {
namespace testing_support {

struct Outcome {
  int status = -1;         ///< exit status; -1 when the process did not exit
  bool signalled = false;  ///< killed by a signal: a crash
  std::string out, err;    ///< standard output and standard error
};

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh, empty directory `name` in the test's own scratch folder (scratch.h).
inline std::filesystem::path fresh_directory(const std::string& name) { return scratch_subdir(name); }

/// Runs `command` through the shell with standard input closed. Standard output and
/// error go through `log_dir`/`tag`.out and .err, removed again before returning, so
/// a test may list `log_dir` for the files the program itself left.
inline Outcome run_command(const std::string& command, const std::filesystem::path& log_dir,
                           const std::string& tag = "run") {
  const std::filesystem::path out = log_dir / (tag + ".out"), err = log_dir / (tag + ".err");
  const std::string redirected =
      command + " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
  const int raw = std::system(redirected.c_str());
  Outcome r;
  r.signalled = WIFSIGNALED(raw);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace testing_support
}  // namespace specular
