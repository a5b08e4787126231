// For the tests that check what a test records in the functional coverage (issue 37):
// runs one test of the running executable in a child process with
// SPECULAR_FUNCTIONAL_COVERAGE set to a scratch folder of its own, and returns the hits
// the child wrote (every fcov-*.tsv file summed). A recorder that stops recording, or
// records the wrong bin, then fails a test instead of only leaving a bin unhit in a
// report nobody runs.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "scratch.h"
#include "subprocess.h"

namespace specular {
namespace testing_support {

/// Bin name -> hits of the test `filter` (a --gtest_filter) run in a child process.
inline std::map<std::string, long> hits_of_child(const std::string& filter) {
  const std::filesystem::path folder = scratch_subdir("fcov_" + scratch_detail::path_safe(filter));
  const std::filesystem::path log = scratch_subdir("log_" + scratch_detail::path_safe(filter));
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const Outcome child = run_command("SPECULAR_FUNCTIONAL_COVERAGE='" + folder.string() + "' '" + self +
                                        "' --gtest_filter='" + filter + "'",
                                    log, "child");
  EXPECT_EQ(child.status, 0) << filter << "\n" << child.out << child.err;
  EXPECT_NE(child.out.find("[  PASSED  ] 1 test"), std::string::npos) << filter << ": not exactly one test ran";
  std::map<std::string, long> hits;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    std::ifstream in(entry.path());
    std::string name;
    long count = 0;
    while (std::getline(in, name, '\t') && in >> count) {
      hits[name] += count;
      in.ignore(1, '\n');
    }
  }
  return hits;
}

/// The hits of `hits` whose bin name starts with `prefix`.
inline std::map<std::string, long> hits_under(const std::map<std::string, long>& hits, const std::string& prefix) {
  std::map<std::string, long> picked;
  for (const auto& [name, count] : hits)
    if (name.rfind(prefix, 0) == 0) picked[name] = count;
  return picked;
}

}  // namespace testing_support
}  // namespace specular
