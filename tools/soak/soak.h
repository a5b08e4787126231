// specular_soak: a long constrained-random run through the core, the pin-level device
// and the TLM target, with a scoreboard against the double reference and bit
// equality of the pin and TLM models with the core (issue 5, item 4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "input.h"
#include "specular/core.h"
#include "specular/tlm/pin_target.h"

namespace specular {
namespace cli {
class Command;
}  // namespace cli
}  // namespace specular

namespace specular {
namespace soak {

struct SoakOptions {
  std::size_t core_ops = 10000000;  ///< through Core::run, every policy in turn
  std::size_t pin_ops = 1000000;    ///< through the pin-level device (PinHarness)
  std::size_t tlm_ops = 1000000;    ///< through the TLM `lt` target (SpecularDriver)
  std::size_t tlm_pin_ops = 100000;  ///< through the TLM `pin` target (transactor)
  /// --pin-delay: the TLM pin target's delay policy (PinTargetSettings::delay, issue 35).
  PinDelay pin_delay = PinTargetSettings{}.delay;
  std::uint64_t seed = 1;
  /// The device's constants (pins 19, 20, ROM 38's scale) in every stage; the
  /// reference and the core follow it.
  Constants constants = Constants::patent;
  /// Corrupts the result of operation K (1-based) of every stage, to show that the
  /// scoreboard catches it (0: none).
  std::size_t inject_fault = 0;
  bool quiet = false;  ///< no progress line (drawn on standard error only on a terminal)
};

/// Declares the options on `app` (run_support/cli.h), each writing into `options`.
void add_soak_options(specular::cli::Command& app, SoakOptions& options);
/// What the soak does, for --help: before and after the options.
extern const char* const soak_description;
extern const char* const soak_footer;

/// Constrained-random operands: the corners that matter weigh more than a uniform
/// draw gives them — cos = 0 and 1, the codes just below 1 (pass 1 multiplies their
/// error by n), tiny codes, the codes where A turns negative (x = −3); n = 1 and 1000;
/// R, G, B = 0 and 255; runs of operations that share n and R, G, B (the streaming
/// protocol) as well as changes on every operation.
class Stimuli {
 public:
  Stimuli(const Formats& formats, std::uint64_t seed);
  /// Replaces `chunk` with `count` operations.
  void next(std::vector<tb::Stimulus>& chunk, std::size_t count);

 private:
  std::uint64_t below(std::uint64_t span);  // uniform in [0, span)
  code_t cos_code(unsigned n);
  Formats formats_;
  std::mt19937_64 engine_;
  unsigned run_left_ = 0;
  unsigned n_ = 1;
  std::array<unsigned, 3> rgb_{};
};

/// What one stage found.
struct StageFigures {
  std::string stage;
  std::size_t ops = 0;
  std::size_t mismatches = 0;          ///< operations with any failure below
  std::size_t reference_failures = 0;  ///< outside reference.h's tolerances
  std::size_t bit_mismatches = 0;      ///< pin/TLM result differs from the core's
  double seconds = 0;
  long rss_early_kib = 0;  ///< VmRSS after about a tenth of the stage's operations
  long rss_late_kib = 0;   ///< VmRSS at the end of the stage
  /// TLM stages: the target's CONFIG register (its policies, constants in bits 6:5),
  /// read over the bus; −1 for the other stages.
  long long config_register = -1;
};

/// Resident memory now (VmRSS of /proc/self/status), in KiB; −1 if unavailable.
long resident_kib();

/// "soak <stage>: ops=… mismatches=… …" — one line, key=value, for scripts and tests.
std::string format_figures(const StageFigures& figures);

/// The configuration of the pin and TLM stages: the defaults with options.constants.
Config soak_config(const SoakOptions& options);

/// Cycles through every normalisation x saturation the device accepts under
/// options.constants (soak_config); `skipped` gets the refused ones.
StageFigures run_core_stage(const SoakOptions& options, std::vector<std::string>* skipped = nullptr);
/// These elaborate a SystemC design: call each once per process (specular_soak runs
/// each in a child process of its own).
StageFigures run_pin_stage(const SoakOptions& options);
StageFigures run_tlm_stage(const SoakOptions& options, bool pin_target);

}  // namespace soak
}  // namespace specular
