// The command line of specular_tb: parsing and checking every option before any
// SystemC object exists.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "report.h"
#include "run_models.h"
#include "shard.h"

namespace specular {
namespace tb {

/// Where the computations come from (exactly one per run).
enum class StimulusKind { point, input, sweep, random };

/// Largest --random count: the run streams, so this only bounds the run time.
constexpr std::size_t random_count_max = 100000000;

struct Options {
  bool help = false;
  bool version = false;                            ///< --version
  StimulusKind stimulus = StimulusKind::point;
  double cos = 0;                                  ///< --cos (checked: [0, 1])
  long long n = 0;                                 ///< --n (checked: [1, 1000])
  std::array<long long, 3> rgb{255, 255, 255};     ///< --rgb (default full scale)
  std::string input_path;                          ///< --input
  std::size_t random_count = 0;                    ///< --random N
  std::uint64_t seed = 1;                          ///< --seed S
  Model model = Model::pin;                        ///< --model
  Config config{};                                 ///< --policy, --saturation
  std::uint64_t clock_period_ps = 10000;           ///< --clock-period (10 ns)
  std::string vcd_path;                            ///< --vcd (pin-level models and tlm)
  std::string power_csv_path;                      ///< --power-csv (tlm model only)
  std::uint64_t power_window_ns = 1000;            ///< --power-window (tlm model only)
  bool real_views = false;                         ///< --real-views (needs --vcd)
  OutputFormat format = OutputFormat::text;        ///< --format
  std::string output_path;                         ///< --output; empty = standard output
  Shard shard{};                                   ///< --shard I/N (shard.h); 0/1 = all
  std::string partial_path;                        ///< --partial FILE (partial.h)
  bool trace_window = false;                       ///< --trace-ops given
  std::uint64_t trace_first = 0;                   ///< --trace-ops FIRST (from 0)
  std::uint64_t trace_count = 0;                   ///< --trace-ops COUNT (>= 1)
  std::string failure_dir;                         ///< --trace-failures DIR
  std::size_t failure_max = 10;                    ///< --trace-failures-max N
  bool quiet = false;                              ///< --quiet: no progress line
  /// --variant NAME (issue 26): runs that design variant's C++ model (variant.h)
  /// instead of a model of the device; empty = the device (--model).
  std::string variant;
};

/// Largest --trace-failures-max: each file is a few kilobytes, the bound keeps a run
/// whose every operation fails from filling a disk.
constexpr std::size_t failure_traces_max = 1000;

/// Parses argv[1..] (without the program name) and --config's file, through CLI11
/// (run_support/cli.h). Throws UsageError with a message that names the option, the bad
/// value and what is allowed (and, for a value from --config, the file's line).
Options parse_options(const std::vector<std::string>& args);

/// The --help text, from the declarations.
std::string help_text();

}  // namespace tb
}  // namespace specular
