// A progress line on standard error for runs that take a while: operations done,
// total, rate and time left, rewritten in place at most twice a second. Shown only
// when standard error is a terminal and --quiet is not given, so logs, pipes and CI
// output stay as they were (and not while rows are printed on the same terminal).
// One implementation for every long run (library specular_progress): specular_tb, the
// studies' stages (specular_study), the soak's stages (specular_soak), the proofs
// (specular_prove, the farm's proof tasks) and, through the specular_progress tool, the
// gate-level replays (scripts/flows/gatelevel/gatesim.sh).
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace specular {
namespace tb {

/// "  12,345 / 1,021,000 operations (1.2%), 45.6 k/s, 0:21 left": `seconds` since the
/// run began. Rate and time left are left out until something is done. `unit` names
/// what is counted; a `label` comes first ("  pin: 12,345 / ...").
std::string progress_line(std::uint64_t done, std::uint64_t total, double seconds,
                          const std::string& unit = "operations", const std::string& label = "");

class Progress {
 public:
  /// `enabled`: whether to draw at all (a terminal, no --quiet); `unit`, `label`: as
  /// progress_line's.
  Progress(std::ostream& out, std::uint64_t total, bool enabled,
           std::string unit = "operations", std::string label = "");
  /// `done` operations so far; draws when half a second has passed since the last line.
  void update(std::uint64_t done);
  /// Clears the line (the summary follows on a clean line).
  void finish();

 private:
  std::ostream& out_;
  std::uint64_t total_;
  bool enabled_;
  std::string unit_, label_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point started_, last_;
};

/// Whether the progress line is wanted: standard error is a terminal and no --quiet.
bool progress_wanted(bool quiet);

}  // namespace tb
}  // namespace specular
