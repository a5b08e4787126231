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
  return "usage: specular_study [--out DIR] [--quick] [--workers N] [--quiet] [--shard I/N]\n"
         "                      [--partial FILE] [--help]\n"
         "       specular_study --merge PARTIAL... [--out DIR]\n"
         "  Measures the device's approximation of cos^n, its energy integrals and its\n"
         "  fixed-point widths, and writes CSV files for scripts/plot_study.py.\n"
         "  --out DIR    directory for the CSV files (created; default study-output)\n"
         "  --quick      n = 1, 10, 100, 1000 only and coarse grids (a few seconds)\n"
         "  --workers N  worker threads, 1 … 64 (default 2)\n"
         "  --quiet      no progress line (drawn on standard error only when it is a\n"
         "               terminal: items done, total, rate, time left)\n"
         "  --shard I/N  run only the stages s with s mod N = I (0-based; the stages are\n"
         "               0 constants search, 1 error study, 2 energy integrals, 3\n"
         "               device-energy integrals, 4 width exploration, 5 sphere renders)\n"
         "  --partial FILE  write this run's partial result (JSON: settings, commit, shard,\n"
         "               the files written, what the summary needs, timing)\n"
         "  --merge PARTIAL...  gather a complete set of shards' files into --out DIR and\n"
         "               write the unsharded run's summary (exit 2, nothing written, for a\n"
         "               missing, repeated or mismatched shard, named)\n";
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
    } else if (arg == "--shard") {
      options.shard = value();
    } else if (arg == "--partial") {
      options.partial = value();
      if (options.partial.empty()) throw UsageError("--partial needs a file name");
    } else if (arg == "--merge") {
      while (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) options.merge_files.push_back(argv[++i]);
      if (options.merge_files.empty()) throw UsageError("--merge needs the partial files of every shard");
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
