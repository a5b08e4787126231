// A verilated design variant (rtl/design_space/specular_NAME.v, docs/design_space/flow.md "Conventions (every variant follows them)")
// driven through the variants' common ports: operations streamed in, a start on every
// clock the top is ready, results collected in order as valid rises. One template for
// every variant: their ports are the same.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>

#include "rtl_coverage.h"
#include "specular/variants/variant.h"
#if SPECULAR_RTL_COVERAGE
#include "../src/thread_context_guard.h"
#endif

namespace specular {
namespace variants {

/// Sign-extends the low `width` bits of a Verilator port word.
inline code_t sign_extend(std::uint64_t word, int width) {
  const int unused = 64 - width;
  return static_cast<code_t>(word << unused) >> unused;
}

template <class Top>
class VariantRtl {
 public:
  /// Two clocks of reset: the top's registers reach their idle state. Then one clock
  /// out of reset without a start, as a platform's first clocks are: the idle branch of
  /// a top's sequencer (schlick_divider's divider) is exercised too.
  VariantRtl() {
    top_.clk = 0;
    top_.reset_n = 0;
    top_.start = 0;
    top_.eval();
    clock();
    clock();
    top_.reset_n = 1;
    top_.eval();
    clock();
  }

#if SPECULAR_RTL_COVERAGE
  ~VariantRtl() { context_guard_.enter(); }  // the model's scopes unregister from its context
#endif

  /// Runs `count` operations: next(i) gives operation i's Operands, sink(i, result)
  /// takes its result, in order. Throws std::runtime_error if the top stays without a
  /// result for `max_wait` clocks (a variant that never answers).
  template <class Next, class Sink>
  void stream(std::size_t count, Next&& next, Sink&& sink, std::size_t max_wait = 1000) {
    std::size_t issued = 0, done = 0, idle = 0;
    std::deque<std::size_t> in_flight;
    while (done < count) {
      const bool take = issued < count && top_.ready;
      if (take) {
        const Operands in = next(issued);
        top_.cos = static_cast<std::uint32_t>(in.cos);
        top_.n = static_cast<std::uint32_t>(in.n);
        top_.r = static_cast<std::uint32_t>(in.rgb[0]);
        top_.g = static_cast<std::uint32_t>(in.rgb[1]);
        top_.b = static_cast<std::uint32_t>(in.rgb[2]);
        in_flight.push_back(issued++);
      }
      top_.start = take;
      clock();
      ++clocks_;
      if (top_.valid) {
        if (in_flight.empty()) throw std::runtime_error("variant: valid without a start in flight");
        VariantResult result;
        result.lobe = sign_extend(top_.lobe, lobe_bits);
        result.out = {sign_extend(top_.out_r, out_bits), sign_extend(top_.out_g, out_bits),
                      sign_extend(top_.out_b, out_bits)};
        sink(in_flight.front(), result);
        in_flight.pop_front();
        ++done;
        idle = 0;
      } else if (++idle > max_wait) {
        throw std::runtime_error("variant: no result for " + std::to_string(max_wait) +
                                 " clocks after operation " + std::to_string(done));
      }
    }
    top_.start = 0;
  }

  /// Clocks run so far (after reset): the harness's measure of cycles per result.
  std::uint64_t clocks() const { return clocks_; }

  static constexpr int lobe_bits = 31;  ///< multiplier 39's format, S10.20
  static constexpr int out_bits = 32;   ///< pins 24–26, S18.13

 private:
  /// One clock: inputs are sampled at the rising edge; outputs read after it.
  void clock() {
    top_.clk = 1;
    top_.eval();
    top_.clk = 0;
    top_.eval();
  }

#if SPECULAR_RTL_COVERAGE
  // The RTL coverage build (rtl_coverage.h): a context of the model's own, so its counts
  // are its own, read before the model goes.
  VerilatedContext context_;
  ThreadContextGuard context_guard_{context_};  // between the two (thread_context_guard.h)
  Top top_{&context_};
  RtlCoverageScope coverage_{context_};
#else
  Top top_;
#endif
  std::uint64_t clocks_ = 0;
};

}  // namespace variants
}  // namespace specular
