// Issue 20: an idle target costs (almost) nothing. The pin target's clock (pin 28)
// runs on demand: no edges while no operation runs, so simulated time advances over
// an idle target without work proportional to it (pin 28's changes counted, pending
// events checked, never timed), and sc_start() without a time end returns once the initiator
// is done — on lt, pin and rtl alike.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

#include "support/legal_use_bench.h"

namespace specular {
namespace {

using namespace tlm_testing;
using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_MS;

const sc_time period(10, SC_NS);

/// Counts every change of pin 28, whatever drives it (the work an idle clock costs).
struct EdgeCounter : sc_core::sc_module {
  EdgeCounter(sc_core::sc_module_name name, const sc_core::sc_signal_in_if<bool>& clock)
      : sc_module(name) {
    SPECULAR_HAS_PROCESS(EdgeCounter);
    SC_METHOD(count);
    sensitive << clock.value_changed_event();
    dont_initialize();
  }
  void count() { ++edges; }
  long edges = 0;
};

// No traffic at all: 1 ms and then 9 ms more of simulated time (100 000 and 900 000
// clock periods) pass with pin 28 never changing and nothing left to schedule.
TEST(TlmIdle, IdlePinTargetAdvancesTimeWithoutWork) {
  static LegalUseBench bench("bench", Target::pin, Config{}, period);  // no thread started
  const auto& target = static_cast<const SpecularPinTarget&>(*bench.target);
  static EdgeCounter counter("counter", target.harness.pin28());
  sc_core::sc_start(1, SC_MS);
  const long edges_after_1ms = counter.edges;
  sc_core::sc_start(9, SC_MS);
  EXPECT_EQ(sc_core::sc_time_stamp(), sc_time(10, SC_MS));
  EXPECT_EQ(counter.edges, 0) << "pin 28 toggled while idle (" << edges_after_1ms << " in 1 ms)";
  EXPECT_EQ(target.harness.clock_rises(), 0u);
  EXPECT_FALSE(sc_core::sc_pending_activity()) << "an idle target keeps events scheduled";
}

// The rtl target clocks its verilated model inside the initiator's calls and owns no
// process: idle, it schedules nothing at all, so time runs over it for free.
TEST(TlmIdle, IdleRtlTargetSchedulesNothing) {
  static LegalUseBench bench("bench", Target::rtl, Config{}, period);  // no thread started
  sc_core::sc_start(1, SC_MS);
  EXPECT_FALSE(sc_core::sc_pending_activity()) << "an idle rtl target keeps events scheduled";
  sc_core::sc_start(9, SC_MS);
  EXPECT_EQ(sc_core::sc_time_stamp(), sc_time(10, SC_MS));
  EXPECT_FALSE(sc_core::sc_pending_activity());
}

// One initiator thread: an operation, 1 ms (100 000 periods) of its own work, a second
// operation, then it ends. sc_start() returns by itself shortly after the second
// operation, the results equal Core's, and the clock rose only around the operations.
class TlmIdleEnds : public testing::TestWithParam<Target> {};

TEST_P(TlmIdleEnds, SimulationEndsWhenTheInitiatorIsDone) {
  static std::unique_ptr<LegalUseBench> bench;
  bench = std::make_unique<LegalUseBench>("bench", GetParam(), Config{}, period);
  sc_time last_done;
  bench->start(nullptr, 1, [&](LegalUseBench& b, int) {
    Operands op;
    op.cos = 60000;
    op.n = 12;
    op.rgb = {255, 128, 7};
    b.single(Path::b, Path::b, op);
    sc_core::wait(1, SC_MS);
    op.cos = 65000;
    b.single(Path::nb_accepted, Path::b, op);
    last_done = sc_core::sc_time_stamp();
  });
  bench->stop_when_done = false;  // the kernel must run out of events by itself
  sc_core::sc_start();
  for (const std::string& failure : bench->failures) ADD_FAILURE() << failure;
  EXPECT_TRUE(bench->checker.violations.empty());
  EXPECT_EQ(bench->compared, 6);
  EXPECT_GE(sc_core::sc_time_stamp(), last_done);
  // After the last operation only the clock's idle tail may run (pin), nothing (lt, rtl).
  EXPECT_LE(sc_core::sc_time_stamp(),
            last_done + period * (PinHarness::idle_tail_rises + 1)) << "events after the work";
  if (GetParam() == Target::pin) {
    const auto& pin = static_cast<const SpecularPinTarget&>(*bench->target);
    // Each operation: a reset period (the first), T/4..5T/4 to the start edge, 2.5 T
    // to pin 35, the idle tail: well under 20 rises for both, against 100 000 for a
    // clock that ran through the 1 ms between them.
    EXPECT_GT(pin.harness.clock_rises(), 0u);
    EXPECT_LT(pin.harness.clock_rises(), 20u);
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, TlmIdleEnds, testing::Values(Target::lt, Target::pin, Target::rtl),
                         [](const testing::TestParamInfo<Target>& info) {
                           return std::string(to_string(info.param));
                         });

}  // namespace
}  // namespace specular
