// Runs a study stage over many independent items (one exponent n each) on a few
// worker threads, and reports progress on stderr while it runs.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace specular {
namespace study {

/// Calls work(item, worker) for every item in [0, items) on `workers` threads
/// (std::thread); items are handed out one at a time, so uneven items balance.
/// Prints a line naming the stage on stderr, then specular_tb's progress line (items
/// done, total, rate, time left; progress.h) while it runs when stderr is a terminal
/// and not `quiet`, then a final line with the stage's time. An exception in `work`
/// stops the stage and is rethrown here. Returns the stage's wall time in seconds.
double parallel_for(const std::string& stage, std::size_t items, unsigned workers, bool quiet,
                    const std::function<void(std::size_t item, unsigned worker)>& work);

}  // namespace study
}  // namespace specular
