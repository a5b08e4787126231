// The --sweep grid (every n × 1021 cos values) as the operand source of
// tb::run_operations, keeping only the operations of one shard of n
// (support/operation_shard.h); `stimuli` holds the chunk's stimuli, aligned with the
// operands handed on, for the scoreboard.
#pragma once

#include <algorithm>
#include <vector>

#include "input.h"
#include "run_models.h"
#include "operation_shard.h"

namespace specular {
namespace testing_support {

inline tb::OperandSource sharded_sweep(tb::SweepSource& sweep, std::vector<tb::Stimulus>& stimuli,
                                       OperationShard shard) {
  return [&sweep, &stimuli, shard](std::vector<Operands>& chunk, std::size_t max) {
    chunk.clear();
    while (chunk.empty()) {  // a chunk may hold no n of the shard: take the next one
      if (!sweep.next(stimuli, max)) return false;
      stimuli.erase(std::remove_if(stimuli.begin(), stimuli.end(),
                                   [&shard](const tb::Stimulus& s) { return !shard.covers(s.operands.n); }),
                    stimuli.end());
      for (const tb::Stimulus& s : stimuli) chunk.push_back(s.operands);
    }
    return true;
  };
}

}  // namespace testing_support
}  // namespace specular
