// libFuzzer target: transaction SEQUENCES on every target (issue 20). Each input is
// decoded into 1–3 initiator threads, each with its own list of accesses — batches
// through its own part of the batch window, single operations through OPERANDS and
// RESULTS, operand changes, debug reads, pauses — and each access travels by
// b_transport or by nb_transport_fw with any answer a legal initiator may give to
// BEGIN_RESP (TLM_COMPLETED, TLM_UPDATED/END_RESP, TLM_ACCEPTED + END_RESP) and any
// BEGIN_REQ delay. The same threads run against `lt`, `pin` and `rtl` side by side,
// each behind the tests' base-protocol checker (tests/support/). Findings:
//   - a SystemC error (e.g. two writers of a pin: it throws out of sc_start), a crash,
//     undefined behaviour (ASan/UBSan);
//   - a protocol breach seen by the checker, an nb transaction left half way;
//   - a response other than TLM_OK_RESPONSE (every access generated is legal);
//   - a result different from Core::run: batch results exactly; a single operation's
//     results exactly with one thread, else equal to Core on one of the input's cos
//     codes (N, R, G, B are then shared by all threads);
//   - a debug read of N, R, G, B that differs from what was written.
//
// The design is elaborated once in LLVMFuzzerInitialize; each input wakes the worker
// threads, and when they are done the driver thread pauses the kernel (sc_pause).
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "specular/report_ids.h"
#include "support/legal_use_bench.h"

// libsystemc refers to sc_main; libFuzzer's main() runs instead, so it is never called.
extern "C" int sc_main(int, char**) { return 0; }

namespace {

using namespace specular;
using namespace specular::tlm_testing;
using sc_core::sc_time;
using sc_core::SC_NS;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_tlm_sequences: %s\n", what.c_str());
  std::abort();
}

/// Reads the input as a little stream of bytes; past its end every read gives 0.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return at_ >= size_; }
  std::uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
  std::uint32_t u24() { return u8() | (static_cast<std::uint32_t>(u8()) << 8) | (static_cast<std::uint32_t>(u8()) << 16); }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

constexpr std::uint32_t region_words = 64;  ///< each thread's part of the batch window
constexpr std::size_t max_actions = 32;     ///< per input, over all threads

struct Action {
  enum Kind : std::uint8_t { batch, single, shared, debug, pause, kinds } kind;
  Path write, read;
  sc_time delay;
  std::vector<std::uint32_t> cos;  ///< batch: the codes; single: one code
  std::uint32_t first = 0;         ///< batch: word within the thread's region
  code_t n = 1;                    ///< shared
  std::array<code_t, 3> rgb{};     ///< shared
};

struct Plan {
  int threads = 1;
  code_t n = 1;
  std::array<code_t, 3> rgb{};
  std::vector<std::vector<Action>> actions;  ///< per thread
  std::set<std::uint32_t> cos_used;          ///< every cos code of the input
};

Path path_of(std::uint8_t b) { return static_cast<Path>(b % static_cast<int>(Path::count)); }

Plan decode(Bytes in) {
  Plan plan;
  plan.threads = 1 + in.u8() % 3;  // Driver::max_threads
  plan.n = 1 + in.u24() % 1000;
  plan.rgb = {in.u8(), in.u8(), in.u8()};
  plan.actions.resize(plan.threads);
  for (std::size_t i = 0; i < max_actions && !in.empty(); ++i) {
    Action a;
    const std::uint8_t head = in.u8();
    const int thread = head % plan.threads;
    a.kind = static_cast<Action::Kind>((head >> 2) % Action::kinds);
    if (a.kind == Action::shared && plan.threads > 1) a.kind = Action::debug;  // exactness
    const std::uint8_t paths = in.u8();
    a.write = path_of(paths);
    a.read = path_of(paths >> 4);
    a.delay = sc_time(in.u8() % 40, SC_NS);
    switch (a.kind) {
      case Action::batch: {
        const std::uint32_t k = 1 + in.u8() % 8;
        a.first = in.u8() % (region_words - k + 1);
        for (std::uint32_t j = 0; j < k; ++j) a.cos.push_back(in.u24() % 65537);
        break;
      }
      case Action::single: a.cos.push_back(in.u24() % 65537); break;
      case Action::shared:
        a.n = 1 + in.u24() % 1000;
        a.rgb = {in.u8(), in.u8(), in.u8()};
        break;
      default: break;
    }
    for (const std::uint32_t c : a.cos) plan.cos_used.insert(c);
    plan.actions[thread].push_back(std::move(a));
  }
  return plan;
}

class Driver : public sc_core::sc_module {
 public:
  explicit Driver(sc_core::sc_module_name name) : sc_module(name) {
    SPECULAR_HAS_PROCESS(Driver);
    for (const Target kind : {Target::lt, Target::pin, Target::rtl})
      benches.push_back(std::make_unique<LegalUseBench>(to_string(kind), kind, Config{}, period));
    SC_THREAD(run);
    // Worker threads live as long as the design: the socket's nb-to-b threads are
    // spawned as their children, and a child that outlives a finished dynamic parent
    // leaves SystemC's name bookkeeping behind (LeakSanitizer reports it).
    for (auto& bench : benches)
      for (int t = 0; t < max_threads; ++t)
        sc_core::sc_spawn([this, b = bench.get(), t] { serve(*b, t); },
                          (std::string(bench->basename()) + "_worker" + std::to_string(t)).c_str());
  }

  void start(const Plan& plan) {
    plan_ = &plan;
    go_.notify(sc_core::SC_ZERO_TIME);
  }

  const sc_time period{10, SC_NS};
  std::vector<std::unique_ptr<LegalUseBench>> benches;

 private:
  void run() {
    for (;;) {
      wait(go_);
      for (auto& bench : benches) bench->set_shared(Path::b, plan_->n, plan_->rgb);
      running_ = static_cast<int>(benches.size()) * plan_->threads;
      work_.notify(sc_core::SC_ZERO_TIME);
      while (running_ > 0) wait(ended_);
      sc_core::sc_pause();
    }
  }

  void serve(LegalUseBench& bench, int thread) {
    for (;;) {
      sc_core::wait(work_);
      if (thread < plan_->threads) worker(bench, thread);
    }
  }

  void worker(LegalUseBench& bench, int thread) {
    code_t n = plan_->n;
    std::array<code_t, 3> rgb = plan_->rgb;
    for (const Action& a : plan_->actions[thread]) {
      switch (a.kind) {
        case Action::batch:
          bench.batch(a.write, a.read, thread * region_words + a.first, a.cos, n, rgb, a.delay);
          break;
        case Action::single: {
          Operands op;
          op.cos = a.cos.front();
          op.n = n;
          op.rgb = rgb;
          const bool exact = plan_->threads == 1;
          const auto out = bench.single(a.write, a.read, op, a.delay, exact);
          if (!exact) {
            bool known = false;
            for (const std::uint32_t c : plan_->cos_used) {
              op.cos = c;
              const Result r = bench.core.run(op);
              known |= out[0] == r.out[0] && out[1] == r.out[1] && out[2] == r.out[2];
            }
            if (!known) bench.fail("single operation: results of no operation of this input");
          }
          break;
        }
        case Action::shared:
          n = a.n;
          rgb = a.rgb;
          bench.set_shared(a.write, n, rgb);
          break;
        case Action::debug: {
          std::uint32_t words[4] = {};
          if (bench.cpu.debug(tlm::TLM_READ_COMMAND, offset_of(Reg::n), words, 16) != 16)
            bench.fail("debug read of N, R, G, B short");
          if (words[0] != n || words[1] != rgb[0] || words[2] != rgb[1] || words[3] != rgb[2])
            bench.fail("debug read of N, R, G, B: not what was written");
          break;
        }
        default: sc_core::wait(a.delay + sc_time(1, SC_NS)); break;
      }
    }
    if (--running_ == 0) ended_.notify(sc_core::SC_ZERO_TIME);
  }

  static constexpr int max_threads = 3;
  const Plan* plan_ = nullptr;
  sc_core::sc_event go_, work_, ended_;
  int running_ = 0;
};

Driver* driver = nullptr;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  // The pin device's own protocol reports are findings too: every access is legal.
  for (const char* type : report::protocol_types)
    sc_core::sc_report_handler::set_actions(type, sc_core::SC_DISPLAY | sc_core::SC_ABORT);
  driver = new Driver("fuzz");  // lives until exit, as SystemC wants
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Plan plan = decode(Bytes(data, size));
  driver->start(plan);
  sc_core::sc_start();
  for (auto& bench : driver->benches) {
    const std::string name = bench->name();
    for (const std::string& failure : bench->failures) finding(name + ": " + failure);
    for (const std::string& breach : bench->checker.violations) finding(name + ": protocol: " + breach);
    if (!bench->checker.idle()) finding(name + ": an nb transaction was left half way");
  }
  return 0;
}
