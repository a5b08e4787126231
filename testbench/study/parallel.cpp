#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace specular {
namespace study {

double parallel_for(const std::string& stage, std::size_t items, unsigned workers,
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
  int reported_tenths = 0;

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
      ++done;
      const int tenths = static_cast<int>(10 * done / items);
      if (tenths > reported_tenths && done < items) {
        reported_tenths = tenths;
        std::fprintf(stderr, "  %s: %d%% (%zu/%zu, %.1f s)\n", stage.c_str(),
                     static_cast<int>(100 * done / items), done, items, seconds());
      }
    }
  };

  std::fprintf(stderr, "%s: %zu items on %u worker%s\n", stage.c_str(), items, workers,
               workers == 1 ? "" : "s");
  std::vector<std::thread> threads;
  const unsigned count = std::max(1u, workers);
  for (unsigned id = 1; id < count; ++id) threads.emplace_back(worker, id);
  worker(0);
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);

  const double elapsed = seconds();
  std::fprintf(stderr, "  %s: done in %.1f s\n", stage.c_str(), elapsed);
  return elapsed;
}

}  // namespace study
}  // namespace specular
