// Command line of specular_study, and the sampling each stage uses (full or quick).
#pragma once

#include <string>
#include <vector>

namespace specular {
namespace cli {
class Command;
}  // namespace cli
}  // namespace specular

namespace specular {
namespace study {

struct StudyOptions {
  std::string out_dir = "study-output";  ///< where the CSV files go
  bool quick = false;                    ///< a few n and coarse grids: seconds, for tests
  unsigned workers = 2;                  ///< worker threads
  bool quiet = false;                    ///< no progress line (it is drawn only on a terminal)
  std::string shard = "0/1";               ///< --shard I/N: the stages s with s mod N = I
  std::string partial;                     ///< --partial FILE: this run's partial result
  std::vector<std::string> merge_files;    ///< --merge FILE...: merge these partials

  /// Every n the per-n stages visit: 1 … 1000, or a handful in quick mode.
  std::vector<unsigned> n_values() const;
  /// The exponents the error curves and the sphere renders show.
  static std::vector<unsigned> curve_n_values();   ///< 1, 2, 5, 10, 50, 100, 500, 1000
  static std::vector<unsigned> sphere_n_values();  ///< 1, 10, 100, 1000
};

/// Declares the options on `app` (run_support/cli.h), each writing into `options`.
void add_study_options(specular::cli::Command& app, StudyOptions& options);

}  // namespace study
}  // namespace specular
