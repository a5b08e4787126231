// One sharding convention for every long job (issue 25): `--shard I/N`, I the 0-based
// index, N the count, as Slurm (SLURM_ARRAY_TASK_ID), LSF, SGE and Kubernetes Indexed
// Jobs hand them out. The N shards of a run together perform exactly the unsharded
// run's operations, each once, and every operation keeps its place (its index) in the
// unsharded run, so a merge finds the same maxima at the same places.
//
//   --sweep            by n: shard I runs every n with (n - 1) mod N == I, the split of
//                      tests/support/operation_shard.h (SPECULAR_OPERATION_SHARD);
//   --random, --input  by operation index: shard I runs the contiguous block
//                      [floor(I*C/N), floor((I+1)*C/N)) of the C operations; a random
//                      shard draws (and skips) the operations before its block, so its
//                      draws are the unsharded run's, never a reseeded stream.
#pragma once

#include <cstddef>
#include <string>
#include <utility>

namespace specular {
namespace tb {

struct Shard {
  std::size_t index = 0;  ///< I, 0-based
  std::size_t count = 1;  ///< N; 1 = the whole run
  bool whole() const { return count == 1; }
  /// "I/N"
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// Largest N: as many shards as a farm can usefully run (each at least one operation).
constexpr std::size_t shard_count_max = 1000000;

/// Parses "I/N" (0 <= I < N <= shard_count_max); throws UsageError naming the text and
/// the allowed range.
Shard parse_shard(const std::string& text);

/// The block [first, second) of `total` operations that `shard` runs (by index).
std::pair<std::size_t, std::size_t> shard_block(std::size_t total, const Shard& shard);

/// True when the sweep's shard `shard` runs n (split by n).
inline bool shard_has_n(unsigned n, const Shard& shard) {
  return (n - 1) % shard.count == shard.index;
}

}  // namespace tb
}  // namespace specular
