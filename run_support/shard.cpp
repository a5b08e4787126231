#include "shard.h"

#include <cstdint>

#include "parse_values.h"
#include "usage_error.h"

namespace specular {
namespace tb {

Shard parse_shard(const std::string& text) {
  const std::string form = "I/N with 0 <= I < N <= " + std::to_string(shard_count_max);
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos)
    throw UsageError("--shard: '" + text + "' is not " + form + " (e.g. 0/4)");
  const std::string range_n = "[1, " + std::to_string(shard_count_max) + "]";
  const long long count = parse_integer(text.substr(slash + 1), "N", range_n);
  if (count < 1 || static_cast<unsigned long long>(count) > shard_count_max)
    throw UsageError("--shard: N = " + text.substr(slash + 1) + " is outside the allowed range " + range_n);
  const std::string range_i = "[0, " + std::to_string(count - 1) + "]";
  const long long index = parse_integer(text.substr(0, slash), "I", range_i);
  if (index < 0 || index >= count)
    throw UsageError("--shard: I = " + text.substr(0, slash) + " is outside the allowed range " +
                     range_i + " (I is 0-based, below N = " + std::to_string(count) + ")");
  return Shard{static_cast<std::size_t>(index), static_cast<std::size_t>(count)};
}

std::pair<std::size_t, std::size_t> shard_block(std::size_t total, const Shard& shard) {
  // total * i fits in 64 bits: total <= 1e8 (random_count_max) or a file's lines, i <= 1e6.
  const auto at = [&](std::size_t i) {
    return static_cast<std::size_t>(static_cast<std::uint64_t>(total) * i / shard.count);
  };
  return {at(shard.index), at(shard.index + 1)};
}

}  // namespace tb
}  // namespace specular
