// Partial results of sharded runs (issue 25) and their merge.
//
// `specular_tb ... --shard I/N --partial FILE` writes FILE: what the run was (settings
// that every shard of one run shares, the commit of the build), which shard, its
// summary with each maximum's place (operation index) and the results' checksum, and
// its own timing. `specular_tb --merge FILE...` checks that the files are one complete
// set (every index 0..N-1 once, the same settings, the same commit) and reports what
// the unsharded run reports: the same summary, PASS/FAIL and exit status.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "json_report.h"
#include "partial_set.h"
#include "shard.h"

namespace specular {
namespace tb {

/// The partial file's "kind" (a merge refuses any other; the frame: partial_set.h).
constexpr const char* partial_kind = "specular_tb partial result";

/// The settings every shard of a run shares: the unsharded run's description, every
/// width, the sweep's RGB and a checksum of an input file's operations.
Json partial_settings(const RunDescription& whole, const std::array<long long, 3>& rgb,
                      std::uint64_t input_checksum);

/// The whole partial document.
Json partial_json(const Json& settings, const Shard& shard, const Summary& summary,
                  const ShardTiming& timing);

/// `specular_tb --merge FILE... [--format text|json] [--output FILE] [--partial FILE]`:
/// `args` are those after --merge. Returns the exit status (0 PASS, 1 FAIL, 2 refused).
int run_merge(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace tb
}  // namespace specular
