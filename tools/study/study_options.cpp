#include "study_options.h"

#include "cli.h"
#include "shard.h"
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

void add_study_options(specular::cli::Command& app, StudyOptions& o) {
  const cli::Check non_empty{
      [](std::string& v) { return v.empty() ? std::string("the name is empty") : std::string(); }, ""};
  app.add_option("--out", o.out_dir, "directory for the CSV files (created)")
      ->type_name("DIR")
      ->capture_default_str()
      ->check(non_empty);
  app.add_flag("--quick", o.quick, "n = 1, 10, 100, 1000 only and coarse grids (a few seconds)");
  app.add_option("--workers", o.workers, "worker threads")
      ->type_name("N")
      ->capture_default_str()
      ->check(cli::integer_in(1, 64));
  app.add_flag("--quiet", o.quiet,
               "no progress line (drawn on standard error only when it is a terminal: items done, "
               "total, rate, time left)");
  app.add_option("--shard", o.shard,
                 "run only the stages s with s mod N = I (0-based; the stages are 0 constants search, "
                 "1 error study, 2 energy integrals, 3 device-energy integrals, 4 width exploration, "
                 "5 sphere renders)")
      ->type_name("I/N")
      ->check(cli::parsed_by(tb::parse_shard));
  app.add_option("--partial", o.partial,
                 "write this run's partial result (JSON: settings, commit, shard, the files written, "
                 "what the summary needs, timing)")
      ->type_name("FILE")
      ->check(non_empty);
  app.add_option("--merge", o.merge_files,
                 "gather a complete set of shards' files into --out DIR and write the unsharded run's "
                 "summary (exit 2, nothing written, for a missing, repeated or mismatched shard, named)")
      ->type_name("PARTIAL")
      ->expected(1, -1);
}

}  // namespace study
}  // namespace specular
