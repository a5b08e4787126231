// Control unit 16 (Fig. 2) alone, against the spec's timing table (§3), half period by
// half period: start's leading edge at a rising clock edge t0, period T. The table is
// written here as the spec gives it; the unit under test is the gate-level netlist.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "specular/control/control_unit16.h"
#include "support/signal_log.h"

namespace specular {
namespace {

using sc_core::sc_time;
using testing_support::SignalLog;

/// One row of the spec's timing table: the state during the half period that starts
/// `half_periods` × T/2 after start's leading edge.
struct Row {
  int half_periods;
  bool q41, q42, q43, write37, done35;
};

// spec §3, "Operation": 0: Q41 ← 1; T/2: Q42 ← 1; T: 37 rises (pass 1), and40 clears
// Q41; 3T/2: Q43 ← 1 (select 36), Q42 ← 0; 2T: 35 falls, 37 rises (pass 2);
// 5T/2: Q43 ← 0, 35 rises (result valid). Idle before and after.
const std::vector<Row> timing_table = {
    //  t/(T/2)  Q41    Q42    Q43=36 37     35
    {-1,         false, false, false, false, true},
    {0,          true,  false, false, false, true},
    {1,          true,  true,  false, false, true},
    {2,          false, true,  false, true,  true},
    {3,          false, false, true,  false, true},
    {4,          false, false, true,  true,  false},
    {5,          false, false, false, false, true},
    {6,          false, false, false, false, true},
    {7,          false, false, false, false, true},
};

/// Every edge of one operation started at t0, from the same table (value after the edge).
struct Edge {
  const char* signal;
  int half_periods;
  bool value;
};
const std::vector<Edge> edges_of_one_operation = {
    {"q41", 0, true},       {"q41", 2, false},      // and40 clears Q41 at T
    {"q42", 1, true},       {"q42", 3, false},
    {"select36", 3, true},  {"select36", 5, false},
    {"write37", 2, true},   {"write37", 3, false},  // pass 1 written at T
    {"write37", 4, true},   {"write37", 5, false},  // pass 2 written at 2T
    {"done35", 4, false},   {"done35", 5, true},    // result valid at 5T/2
    {"and40", 2, false},    {"and40", 3, true},
};

using Event = std::tuple<sc_time, std::string, bool>;

std::vector<Event> expected_edges(const std::vector<sc_time>& starts, const sc_time& period) {
  std::vector<Event> events;
  for (const sc_time& t0 : starts)
    for (const Edge& e : edges_of_one_operation)
      events.emplace_back(t0 + period * (e.half_periods / 2.0), e.signal, e.value);
  std::sort(events.begin(), events.end());
  return events;
}

std::vector<Event> recorded(const SignalLog& log) {
  std::vector<Event> events;
  for (const auto& c : log.changes()) events.emplace_back(c.time, c.signal, c.value);
  std::sort(events.begin(), events.end());
  return events;
}

std::string describe(const std::vector<Event>& events) {
  std::string text;
  for (const auto& [t, signal, value] : events)
    text += "  " + t.to_string() + " " + signal + (value ? " rises\n" : " falls\n");
  return text;
}

/// Control unit 16 with its own clock and pins, a logic analyser on its nets, and a
/// script thread that drives start and reset.
class ControlBench : public sc_core::sc_module {
 public:
  struct Sample {
    sc_time time;
    bool q41, q42, q43, write37, done35;
  };

  ControlBench(sc_core::sc_module_name name, const sc_time& period)
      : sc_module(name),
        period(period),
        clk("clk", period, 0.5, sc_core::SC_ZERO_TIME, true),
        log("log", {{"q41", &cu16.q41},
                    {"q42", &cu16.q42},
                    {"select36", &select36},
                    {"write37", &write37},
                    {"done35", &done35},
                    {"and40", &cu16.and40_y}}) {
    SPECULAR_HAS_PROCESS(ControlBench);
    cu16.start(start);
    cu16.clk(clk);
    cu16.reset_n(reset_n);
    cu16.select36(select36);
    cu16.write37(write37);
    cu16.done35(done35);
    SC_THREAD(run_script);
    SC_METHOD(drive_start);
    sensitive << start_event_;
    dont_initialize();
  }

  void wait_until(const sc_time& t) {
    if (t > sc_core::sc_time_stamp()) wait(t - sc_core::sc_time_stamp());
  }
  /// Start's leading edge at t0 (a rising clock edge); it falls half a period later.
  /// Returns at t0: the pulse's end is driven by drive_start, the one writer of start.
  void start_at(const sc_time& t0) {
    wait_until(t0);
    start_event_.notify();
  }
  void sample_at(const sc_time& t) {
    wait_until(t);
    samples.push_back({t, cu16.q41.read(), cu16.q42.read(), select36.read(), write37.read(),
                       done35.read()});
  }

  const sc_time period;
  sc_core::sc_clock clk;
  wire start{"start"};
  wire reset_n{"reset_n", true};
  wire select36{"select36"};
  wire write37{"write37"};
  wire done35{"done35", true};
  ControlUnit16 cu16{"cu16"};
  SignalLog log;
  std::function<void(ControlBench&)> script;
  std::vector<Sample> samples;

 private:
  void run_script() {
    if (script) script(*this);
    sc_core::sc_stop();
  }
  void drive_start() {
    const bool rising = !start.read();
    start.write(rising);
    if (rising) start_event_.notify(period / 2);
  }
  sc_core::sc_event start_event_{"start_event"};
};

class ControlTiming : public ::testing::TestWithParam<int> {  // clock period in ps
 protected:
  sc_time period() const { return sc_time(GetParam(), sc_core::SC_PS); }
};

// Sample at the quarter point after every edge and compare with the spec's table.
TEST_P(ControlTiming, TimingTableHalfPeriodByHalfPeriod) {
  ControlBench bench("bench", period());
  const sc_time t0 = period() * 3;  // a rising clock edge, after three idle periods
  bench.script = [&](ControlBench& b) {
    for (const Row& row : timing_table) {
      const sc_time quarter_after_edge = t0 + b.period * (row.half_periods / 2.0 + 0.25);
      if (row.half_periods == 0) b.start_at(t0);
      b.sample_at(quarter_after_edge);
    }
  };
  sc_core::sc_start();
  ASSERT_EQ(bench.samples.size(), timing_table.size());
  for (std::size_t i = 0; i < timing_table.size(); ++i) {
    const Row& want = timing_table[i];
    const auto& got = bench.samples[i];
    SCOPED_TRACE("at t0 + " + std::to_string(want.half_periods) + "·T/2 + T/4 (" +
                 got.time.to_string() + ")");
    EXPECT_EQ(got.q41, want.q41) << "Q41";
    EXPECT_EQ(got.q42, want.q42) << "Q42";
    EXPECT_EQ(got.q43, want.q43) << "Q43 = select 36";
    EXPECT_EQ(got.write37, want.write37) << "write 37";
    EXPECT_EQ(got.done35, want.done35) << "done 35";
  }
}

// Every edge of every watched net, delta cycles included: 37 rises exactly twice (T
// and 2T), 35 falls at 2T and rises at 5T/2, and40 clears Q41 at T; no glitches, and
// nothing moves while idle before and after.
TEST_P(ControlTiming, EdgesOfOneOperation) {
  ControlBench bench("bench", period());
  const sc_time t0 = period() * 4;
  bench.script = [&](ControlBench& b) {
    b.start_at(t0);
    b.wait_until(t0 + b.period * 8);
  };
  sc_core::sc_start();
  const auto want = expected_edges({t0}, period());
  const auto got = recorded(bench.log);
  EXPECT_EQ(got, want) << "recorded:\n" << describe(got) << "expected:\n" << describe(want);
  EXPECT_EQ(bench.log.rises("write37").size(), 2u) << "exactly two register-9 writes";
}

// Back to back at the minimum start interval, 2T (spec, Decision "protocol"): the
// second operation's edges are the first's shifted by exactly 2T, nothing else moves.
TEST_P(ControlTiming, BackToBackAtTwoPeriodsShiftsByExactlyTwoPeriods) {
  ControlBench bench("bench", period());
  const sc_time t0 = period() * 2;
  std::vector<sc_time> starts;
  for (int i = 0; i < 5; ++i) starts.push_back(t0 + period() * (2 * i));
  bench.script = [&](ControlBench& b) {
    for (const sc_time& s : starts) b.start_at(s);
    b.wait_until(starts.back() + b.period * 6);
  };
  sc_core::sc_start();
  const auto want = expected_edges(starts, period());
  const auto got = recorded(bench.log);
  EXPECT_EQ(got, want) << "recorded:\n" << describe(got) << "expected:\n" << describe(want);
  EXPECT_EQ(bench.log.rises("write37").size(), 2 * starts.size());
  EXPECT_EQ(bench.log.rises("done35").size(), starts.size());
}

// Start with reset (pin 29) held low: AND 40 holds Q41 reset, nothing moves.
TEST_P(ControlTiming, StartWithResetLowDoesNothing) {
  ControlBench bench("bench", period());
  const sc_time t0 = period() * 3;
  bench.script = [&](ControlBench& b) {
    b.wait_until(t0 - b.period / 4);
    b.reset_n.write(false);
    b.start_at(t0);
    b.wait_until(t0 + b.period * 5.25);  // released at a quarter point, never on an edge
    b.reset_n.write(true);
    b.wait_until(t0 + b.period * 8);
  };
  sc_core::sc_start();
  std::vector<Event> moves;
  for (const auto& e : recorded(bench.log))
    if (std::get<1>(e) != "and40") moves.push_back(e);  // and40 follows reset by design
  EXPECT_TRUE(moves.empty()) << describe(moves);
  EXPECT_EQ(bench.log.falls("and40"), std::vector<sc_time>{t0 - period() / 4});
  EXPECT_EQ(bench.log.rises("and40"), std::vector<sc_time>{t0 + period() * 5.25});
}

// Reset in the middle of an operation, at each quarter point of its five half periods:
// Q41..Q43 clear at once, 37 never rises again, 35 ends high; the next operation then
// follows the table exactly.
TEST_P(ControlTiming, ResetInTheMiddleOfAnOperation) {
  ControlBench bench("bench", period());
  const sc_time T = period();
  // One simulation, one case after another: T/4, 3T/4, 5T/4, 7T/4, 9T/4 after start.
  const std::vector<int> quarters = {1, 3, 5, 7, 9};
  std::vector<sc_time> aborted_starts, reset_times, next_starts;
  struct AfterReset { bool q41, q42, q43; };
  std::vector<AfterReset> after_reset;
  bench.script = [&](ControlBench& b) {
    sc_time t = T * 2;
    for (int quarter : quarters) {
      aborted_starts.push_back(t);
      b.start_at(t);
      const sc_time reset_at = t + T * (quarter / 4.0);
      b.wait_until(reset_at);
      b.reset_n.write(false);
      reset_times.push_back(reset_at);
      b.wait_until(reset_at + T / 8);  // reset is asynchronous: cleared at once
      after_reset.push_back({b.cu16.q41.read(), b.cu16.q42.read(), b.select36.read()});
      b.wait_until(reset_at + T);
      b.reset_n.write(true);  // released at a quarter point, never on an edge
      // The next operation at the next rising edge at least a period later.
      const sc_time next = T * std::ceil((reset_at + T * 1.25) / T);
      next_starts.push_back(next);
      b.start_at(next);
      t = next + T * 4;
      b.wait_until(t - T / 2);
    }
  };
  sc_core::sc_start();
  ASSERT_EQ(after_reset.size(), quarters.size());
  const auto log = recorded(bench.log);
  for (std::size_t i = 0; i < quarters.size(); ++i) {
    SCOPED_TRACE("reset at start + " + std::to_string(quarters[i]) + "·T/4");
    EXPECT_FALSE(after_reset[i].q41);
    EXPECT_FALSE(after_reset[i].q42);
    EXPECT_FALSE(after_reset[i].q43);
    // Between reset and the next start: no rising 37, no falling 35, no rising Q41..Q43.
    for (const auto& [t, signal, value] : log) {
      if (t < reset_times[i] || t >= next_starts[i]) continue;
      EXPECT_FALSE(signal == "write37" && value) << "write pulse at " << t;
      EXPECT_FALSE(signal == "done35" && !value) << "35 fell at " << t;
      EXPECT_FALSE((signal == "q41" || signal == "q42" || signal == "select36") && value)
          << signal << " rose at " << t;
    }
    // The aborted operation wrote register 9 only for the passes before the reset.
    int aborted_writes = 0, next_writes = 0;
    for (const sc_time& t : bench.log.rises("write37")) {
      if (t >= aborted_starts[i] && t <= reset_times[i]) ++aborted_writes;
      if (t >= next_starts[i] && t < next_starts[i] + T * 3) ++next_writes;
    }
    EXPECT_EQ(aborted_writes, quarters[i] < 4 ? 0 : quarters[i] < 8 ? 1 : 2);
    EXPECT_EQ(next_writes, 2);
    // The next operation follows the table: every edge of it, at the table's times.
    std::vector<Event> next_ops;
    for (const auto& e : log)
      if (std::get<0>(e) >= next_starts[i] && std::get<0>(e) < next_starts[i] + T * 3)
        next_ops.push_back(e);
    EXPECT_EQ(next_ops, expected_edges({next_starts[i]}, T)) << describe(next_ops);
    EXPECT_TRUE(bench.done35.read());
  }
}

INSTANTIATE_TEST_SUITE_P(ClockPeriods, ControlTiming, ::testing::Values(10000, 6000, 1000000),
                         [](const auto& info) { return std::to_string(info.param) + "ps"; });

}  // namespace
}  // namespace specular
