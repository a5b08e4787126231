#include "study_options.h"

#include <cstdlib>

#include "specular/format.h"

namespace specular {
namespace study {

std::vector<unsigned> StudyOptions::n_values() const {
  if (quick) return {1, 10, 100, 1000};
  std::vector<unsigned> all;
  for (unsigned n = n_min; n <= n_max; ++n) all.push_back(n);
  return all;
}

std::vector<unsigned> StudyOptions::curve_n_values() { return {1, 2, 5, 10, 50, 100, 500, 1000}; }

std::vector<unsigned> StudyOptions::sphere_n_values() { return {1, 10, 100, 1000}; }

std::string study_usage() {
  return "usage: specular_study [--out DIR] [--quick] [--workers N] [--quiet] [--help]\n"
         "  Measures the device's approximation of cos^n, its energy integrals and its\n"
         "  fixed-point widths, and writes CSV files for scripts/plot_study.py.\n"
         "  --out DIR    directory for the CSV files (created; default study-output)\n"
         "  --quick      n = 1, 10, 100, 1000 only and coarse grids (a few seconds)\n"
         "  --workers N  worker threads, 1 … 64 (default 2)\n"
         "  --quiet      no progress line (drawn on standard error only when it is a\n"
         "               terminal: items done, total, rate, time left)\n";
}

StudyOptions parse_study_options(int argc, const char* const* argv) {
  StudyOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError("option " + arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--out") {
      options.out_dir = value();
      if (options.out_dir.empty()) throw UsageError("--out needs a non-empty directory name");
    } else if (arg == "--quiet") {
      options.quiet = true;
    } else if (arg == "--quick") {
      options.quick = true;
    } else if (arg == "--workers") {
      const std::string text = value();
      char* end = nullptr;
      const long workers = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0')
        throw UsageError("--workers '" + text + "' is not a whole number; allowed: 1 … 64");
      if (workers < 1 || workers > 64)
        throw UsageError("--workers " + text + " is outside the allowed range [1, 64]");
      options.workers = static_cast<unsigned>(workers);
    } else if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  return options;
}

}  // namespace study
}  // namespace specular
