// specular_soak as a subprocess (standard output and error kept), its "soak <stage>:
// key=value ..." lines parsed: shared by the soak's tests (test_long_soak.cpp,
// test_soak_constants.cpp).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "scratch.h"

namespace specular {
namespace testing_support {

inline const std::string soak = std::string(SPECULAR_BINARY_DIR) + "/tools/soak/specular_soak";

struct SoakRun {
  int status = -1;
  std::string out;
  /// stage → key → value, from the "soak <stage>: key=value ..." lines.
  std::map<std::string, std::map<std::string, double>> stages;
};

inline SoakRun run_soak(const std::string& arguments) {
  const std::filesystem::path out = specular::testing_support::scratch_file("soak_out.txt");
  const int raw =
      std::system(("'" + soak + "' " + arguments + " >'" + out.string() + "' 2>&1").c_str());
  SoakRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(out);
  std::stringstream all;
  all << in.rdbuf();
  r.out = all.str();
  std::istringstream lines(r.out);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("soak ", 0) != 0) continue;
    const auto colon = line.find(':');
    const std::string stage = line.substr(5, colon - 5);
    std::istringstream fields(line.substr(colon + 1));
    std::string field;
    while (fields >> field) {
      const auto equals = field.find('=');
      if (equals != std::string::npos)
        r.stages[stage][field.substr(0, equals)] = std::stod(field.substr(equals + 1));
    }
  }
  return r;
}

}  // namespace testing_support
}  // namespace specular
