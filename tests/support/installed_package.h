// The tests that install this build and configure a consumer on it, as a SoC team
// does (the package tests): the build's own cmake, its cache, an install into the test's
// scratch folder. Needs SPECULAR_BINARY_DIR (every test target defines it).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "subprocess.h"

namespace specular {
namespace testing_support {

inline std::string shell_quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

/// A value of the build's CMakeCache.txt (the cmake and the compiler the build used).
inline std::string cache_value(const std::string& name) {
  const std::string cache = slurp(std::filesystem::path(SPECULAR_BINARY_DIR) / "CMakeCache.txt");
  std::smatch m;
  if (!std::regex_search(cache, m, std::regex("\n" + name + ":[A-Z]+=([^\n]*)")))
    ADD_FAILURE() << name << " is not in " << SPECULAR_BINARY_DIR << "/CMakeCache.txt";
  return m.size() > 1 ? m[1].str() : std::string();
}

/// The cmake the build was configured with, quoted for the shell.
inline std::string cmake() { return shell_quoted(cache_value("CMAKE_COMMAND")); }

/// This build installed into `dir`/prefix.
inline std::filesystem::path install(const std::filesystem::path& dir) {
  const std::filesystem::path prefix = dir / "prefix";
  const Outcome r = run_command(cmake() + " --install " + shell_quoted(SPECULAR_BINARY_DIR) +
                                    " --prefix " + shell_quoted(prefix),
                                dir, "install");
  EXPECT_EQ(r.status, 0) << "cmake --install failed (build every target first):\n" << r.out << r.err;
  return prefix;
}

}  // namespace testing_support
}  // namespace specular
