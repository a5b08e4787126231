// Partial results of sharded runs (issue 25): what every tool's partial file holds and
// how a merge reads a complete set of them. specular_tb, specular_prove,
// specular_variant_error and specular_study each write their own "kind" of partial
// (settings, summary) around this frame: kind, version, commit, shard, timing.
#pragma once

#include <string>
#include <vector>

#include "json.h"
#include "shard.h"

namespace specular {
namespace tb {

/// The partial files' layout version (a merge refuses any other).
constexpr int partial_version = 1;

/// The commit the build came from ("unknown" outside a git checkout; "-dirty" appended
/// when the working tree differed from it at build time).
const char* build_commit();

/// What one shard measured of itself.
struct ShardTiming {
  double wall_seconds = 0;  ///< the run, stimulus to summary (elaboration included)
  double cpu_seconds = 0;   ///< user + system CPU of the whole process so far
};

/// The user + system CPU time of this process, in seconds.
double process_cpu_seconds();

/// This machine's name, for a shard's timing ("unknown" if it has none).
std::string host_name();

/// One partial file as read.
struct PartialFile {
  std::string path;
  Json json;
  Shard shard;
};

/// Reads `files` (partials of `kind`) and checks they are one complete set: the same
/// commit, the same settings, the same count N and every index 0..N-1 exactly once.
/// Returns them in index order; throws UsageError naming the offending file or shard.
std::vector<PartialFile> read_complete_set(const std::vector<std::string>& files,
                                          const std::string& kind);

}  // namespace tb
}  // namespace specular
