// specular_tb from its command line to its exit status; main() only calls this.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "input.h"

namespace specular {
namespace tb {

/// Exit statuses of specular_tb.
enum ExitStatus : int {
  exit_pass = 0,            ///< every computation within tolerance
  exit_out_of_tolerance = 1,
  exit_usage = 2,           ///< bad option, value, input file or output path
  exit_internal = 3,        ///< anything else (a SystemC error, …)
};

/// Sees (and may change) each result and its cycles before the scoreboard compares
/// them. specular_tb passes none; tests use it to inject a fault and prove that a
/// miss is reported and gives exit_out_of_tolerance.
using ResultTap = std::function<void(const Stimulus& stimulus, Result& result, double& cycles)>;

/// Parses `args` (without the program name), validates everything, runs the model
/// and writes the report to --output or `out`; messages go to `err`.
/// With the pin model this runs the SystemC kernel: once per process.
int run_testbench(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                  const ResultTap& tap = nullptr);

}  // namespace tb
}  // namespace specular
