// The exhaustive tests' operations split into shards by n (issue 31): with
// SPECULAR_OPERATION_SHARD=I/N in the environment, a long test covers only the n in
// 1..1000 with (n − 1) mod N = I — still every device, every cos code and every policy
// it covers whole, on a 1/N slice of n — and the N shards together are the whole test.
// CI runs one shard of every long test (scripts/test.sh, I from the commit); the whole
// of each runs with `scripts/test.sh --full` (docs/testing.md). Unset: the whole test.
#pragma once

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace specular {
namespace testing_support {

struct OperationShard {
  unsigned index = 0;  ///< I, 0 ≤ I < N
  unsigned count = 1;  ///< N, 1 ≤ N ≤ max_count

  static constexpr unsigned max_count = 1000;  ///< one n per shard at most

  /// Whether operations of exponent `n` (≥ 1) belong to this shard.
  bool covers(unsigned n) const { return (n - 1) % count == index; }

  /// How many n in first..last (first ≥ 1) this shard covers.
  unsigned covered(unsigned first, unsigned last) const {
    unsigned k = 0;
    for (unsigned n = first; n <= last; ++n) k += covers(n) ? 1u : 0u;
    return k;
  }

  bool whole() const { return count == 1; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// Parses "I/N"; an empty or missing text is the whole run. Anything else is refused
/// with a message naming the value and the allowed form.
inline OperationShard parse_operation_shard(const char* text) {
  OperationShard shard;
  if (text == nullptr || *text == '\0') return shard;
  const std::string value(text);
  const auto refuse = [&value]() {
    return std::invalid_argument("SPECULAR_OPERATION_SHARD = '" + value +
                                 "': expected I/N, integers with 0 <= I < N and 1 <= N <= " +
                                 std::to_string(OperationShard::max_count));
  };
  const std::size_t slash = value.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == value.size()) throw refuse();
  const auto number = [&](const std::string& digits) {
    if (digits.size() > 4 || digits.find_first_not_of("0123456789") != std::string::npos)
      throw refuse();
    return static_cast<unsigned>(std::stoul(digits));
  };
  shard.index = number(value.substr(0, slash));
  shard.count = number(value.substr(slash + 1));
  if (shard.count < 1 || shard.count > OperationShard::max_count || shard.index >= shard.count)
    throw refuse();
  return shard;
}

/// The shard this test process runs (SPECULAR_OPERATION_SHARD).
inline OperationShard operation_shard() {
  return parse_operation_shard(std::getenv("SPECULAR_OPERATION_SHARD"));
}

}  // namespace testing_support
}  // namespace specular
