// Verilator's line and toggle coverage of a verilated model, saved for the RTL coverage
// report (issue 37, scripts/verify/rtl_coverage.sh, docs/testing/code_coverage.md "Toggle and line coverage of
// the RTL"). Why here and not at Verilator's own exit hook: every model of the twins and
// variants owns its VerilatedContext, and a context's coverage points are pointers into
// its model's counters, so they must be read while the model lives. An RtlCoverageScope
// declared after the model (so destroyed before it) adds that context's counts into one
// table per process, point by point and instance by instance; at exit the table goes to $SPECULAR_RTL_COVERAGE/rtlcov-<pid>-<random>.dat
// (Verilator's coverage format, merged by verilator_coverage). Without the variable nothing is
// written; in a build without -DSPECULAR_RTL_COVERAGE=ON the scope is empty and nothing is
// compiled in.
#pragma once

#if SPECULAR_RTL_COVERAGE
#include <verilated.h>
#include <verilated_cov.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <random>
#include <set>
#include <sstream>
#include <string>
#else
class VerilatedContext;
#endif

namespace specular {

#if SPECULAR_RTL_COVERAGE
namespace rtl_coverage {

/// The process's counts, by Verilator's point key, written at exit (and again should a
/// model outlive that: one in static storage).
class Table {
 public:
  static Table& instance() {
    static Table* table = new Table;  // never destroyed: a static model may outlive exit
    return *table;
  }
  void enter(VerilatedContext* context) {
    const std::lock_guard<std::mutex> lock(mutex_);
    live_.insert(context);
  }
  /// Adds a live context's counts (its model still exists) and forgets the context.
  void leave(VerilatedContext* context) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (live_.erase(context) == 0 || folder_.empty()) return;
    add(*context);
    if (written_) write();
  }

 private:
  static void at_exit() {
    Table& table = instance();
    const std::lock_guard<std::mutex> lock(table.mutex_);
    // Models not yet destroyed (std::exit from inside a run) are still alive here.
    for (VerilatedContext* context : table.live_) table.add(*context);
    table.live_.clear();
    table.write();
  }
  void write() {
    written_ = true;
    std::ofstream out(folder_ + "/" + name() + ".dat");
    out << "# SystemC::Coverage-3\n";
    for (const auto& [key, count] : counts_) out << "C '" << key << "' " << count << '\n';
  }
  Table() {
    const char* folder = std::getenv("SPECULAR_RTL_COVERAGE");
    if (folder == nullptr || *folder == '\0') return;
    folder_ = folder;
    tag_ = std::random_device()();
    std::atexit(at_exit);
  }
  /// rtlcov-<pid>-<random>: the pid now, so a forked child writes a file of its own.
  std::string name() const {
    std::ostringstream name;
    name << "rtlcov-" << getpid() << '-' << std::hex << tag_;
    return name.str();
  }
  /// Verilator writes a context's points only as a file: written beside the result,
  /// read back into the table, removed.
  void add(VerilatedContext& context) {
    const std::string scratch = folder_ + "/." + name() + ".part";
    context.coveragep()->forcePerInstance(true);  // every instance's nets, not summed per module
    context.coveragep()->write(scratch.c_str());
    std::ifstream in(scratch);
    std::string line;
    while (std::getline(in, line)) {
      const std::size_t close = line.rfind("' ");
      if (line.rfind("C '", 0) != 0 || close == std::string::npos) continue;
      counts_[line.substr(3, close - 3)] += std::strtoull(line.c_str() + close + 2, nullptr, 10);
    }
    std::remove(scratch.c_str());
  }

  std::mutex mutex_;
  std::string folder_;
  unsigned tag_ = 0;
  bool written_ = false;
  std::set<VerilatedContext*> live_;
  std::map<std::string, std::uint64_t> counts_;
};

}  // namespace rtl_coverage

/// Declare after the model of `context` (destroyed before it): its coverage is kept.
class RtlCoverageScope {
 public:
  explicit RtlCoverageScope(VerilatedContext& context) : context_(&context) {
    rtl_coverage::Table::instance().enter(context_);
  }
  RtlCoverageScope(const RtlCoverageScope&) = delete;
  RtlCoverageScope& operator=(const RtlCoverageScope&) = delete;
  ~RtlCoverageScope() { rtl_coverage::Table::instance().leave(context_); }

 private:
  VerilatedContext* context_;
};
#else
/// A build without RTL coverage: nothing to keep.
class RtlCoverageScope {
 public:
  explicit RtlCoverageScope(VerilatedContext& /*context*/) {}
};
#endif

}  // namespace specular
