// specular_tb from its command line to its exit status; main() only calls this.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace specular {
namespace tb {

/// Exit statuses of specular_tb.
enum ExitStatus : int {
  exit_pass = 0,            ///< every computation within tolerance
  exit_out_of_tolerance = 1,
  exit_usage = 2,           ///< bad option, value, input file or output path
  exit_internal = 3,        ///< anything else (a SystemC error, …)
};

/// Parses `args` (without the program name), validates everything, runs the model
/// and writes the report to --output or `out`; messages go to `err`.
/// With the pin model this runs the SystemC kernel: once per process.
int run_testbench(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace tb
}  // namespace specular
