#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <mutex>
#include <thread>
#include <vector>

#include "progress.h"

namespace specular {
namespace study {

double parallel_for(const std::string& stage, std::size_t items, unsigned workers, bool quiet,
                    const std::function<void(std::size_t, unsigned)>& work) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const auto seconds = [&start] {
    return std::chrono::duration<double>(clock::now() - start).count();
  };

  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex report;  // guards `error` and the progress lines
  std::exception_ptr error;
  std::size_t done = 0;
  // specular_tb's progress line (progress.h): only on a terminal, not with --quiet.
  tb::Progress progress(std::cerr, items, tb::progress_wanted(quiet), "items", stage);

  const auto worker = [&](unsigned id) {
    for (;;) {
      if (failed) return;
      const std::size_t item = next++;
      if (item >= items) return;
      try {
        work(item, id);
      } catch (...) {
        std::lock_guard<std::mutex> lock(report);
        if (!error) error = std::current_exception();
        failed = true;
        return;
      }
      std::lock_guard<std::mutex> lock(report);
      progress.update(++done);
    }
  };

  std::cerr << stage << ": " << items << " items on " << workers << " worker"
            << (workers == 1 ? "" : "s") << std::endl;
  std::vector<std::thread> threads;
  const unsigned count = std::max(1u, workers);
  for (unsigned id = 1; id < count; ++id) threads.emplace_back(worker, id);
  worker(0);
  for (std::thread& t : threads) t.join();
  progress.finish();
  if (error) std::rethrow_exception(error);

  const double elapsed = seconds();
  char line[64];
  std::snprintf(line, sizeof line, "%.1f s", elapsed);
  std::cerr << "  " << stage << ": done in " << line << std::endl;
  return elapsed;
}

}  // namespace study
}  // namespace specular
