// Power-on and reset (issue 5, item 5): the datapath registers power on at code 0
// (docs/misuse.md), pin 29 resets only control unit 16 (as in the patent), a start
// before any reset is reported, and a reset mid-operation returns to idle with the
// next operation correct.
#include <gtest/gtest.h>

#include "specular/core.h"
#include "support/functional_coverage_child.h"
#include "support/protocol_bench.h"

namespace specular {
namespace {

using namespace protocol_testing;

Operands operands(double cos, long long n, long long r, long long g, long long b) {
  return Core(Config{}).operands(cos, n, r, g, b);
}

TEST(PowerOn, DatapathRegistersHoldZeroAndTheControlUnitIsIdle) {
  run_scenario(Config{}, [&](ProtocolBench& b) {
    b.at(b.period() / 4);  // the clock has risen once (at 0); nothing else happened
    SpecularDevice& d = b.dut();
    // docs/misuse.md "Power-on and reset": every datapath register holds code 0.
    for (const bus_signal* reg : {&d.reg1_q, &d.reg2_q, &d.reg9_q, &d.reg10_q, &d.reg11_q, &d.reg12_q})
      EXPECT_EQ(reg->read(), 0) << reg->name();
    for (const bus_signal* pin : {&b.harness.pin24_r, &b.harness.pin25_g, &b.harness.pin26_b})
      EXPECT_EQ(pin->read(), 0) << pin->name() << ": K·0·0";
    EXPECT_FALSE(d.cu16.q41.read());
    EXPECT_FALSE(d.cu16.q42.read());
    EXPECT_FALSE(d.select36.read());
    EXPECT_TRUE(b.harness.pin35_done.read()) << "35 idles high (its pulse is active low)";
  });
  EXPECT_EQ(protocol_reports(), 0);
}

TEST(PowerOn, StartBeforeAnyResetIsReportedOnce) {
  const Config config;
  const Operands first = operands(0.75, 9, 255, 255, 255);
  const Operands second = operands(0.99, 400, 10, 20, 30);
  Result before_reset[2];
  Result after_reset;
  run_scenario(config, [&](ProtocolBench& b) {
    before_reset[0] = b.harness.run(first);
    before_reset[1] = b.harness.run(second);
    EXPECT_EQ(reports(report::start_before_reset), 1) << "reported once, not per start";
    b.harness.reset();
    after_reset = b.harness.run(first);
  });
  EXPECT_EQ(reports(report::start_before_reset), 1);
  EXPECT_EQ(protocol_reports(), 1);
  // The model's flip-flops power on cleared, so the results are still right; the
  // report is about a real device, whose state at power-on is unknown.
  expect_matches_reference(config, first, before_reset[0]);
  expect_matches_reference(config, second, before_reset[1]);
  expect_matches_reference(config, first, after_reset);
}

TEST(Reset, ClearsOnlyTheControlUnit) {
  const Operands op = operands(0.9, 33, 120, 130, 140);
  run_scenario(Config{}, [&](ProtocolBench& b) {
    b.harness.reset();
    b.harness.run(op);
    SpecularDevice& d = b.dut();
    const code_t held[] = {d.reg1_q.read(),  d.reg2_q.read(),  d.reg9_q.read(),
                           d.reg10_q.read(), d.reg11_q.read(), d.reg12_q.read(),
                           b.harness.pin24_r.read(), b.harness.pin25_g.read(),
                           b.harness.pin26_b.read()};
    EXPECT_EQ(held[0], op.cos);
    EXPECT_EQ(held[1], op.n);
    for (int ch = 0; ch < 3; ++ch) EXPECT_EQ(held[3 + ch], op.rgb[ch]);
    // Hold reset low across several clock edges.
    const sc_time T = b.period();
    b.at(b.rising_edge_from(sc_core::sc_time_stamp() + T) + T / 4);
    b.harness.pin29_reset_n.write(false);
    b.at(sc_core::sc_time_stamp() + 3 * T);
    const code_t during[] = {d.reg1_q.read(),  d.reg2_q.read(),  d.reg9_q.read(),
                             d.reg10_q.read(), d.reg11_q.read(), d.reg12_q.read(),
                             b.harness.pin24_r.read(), b.harness.pin25_g.read(),
                             b.harness.pin26_b.read()};
    for (int i = 0; i < 9; ++i) EXPECT_EQ(during[i], held[i]) << "datapath net " << i;
    EXPECT_FALSE(d.cu16.q41.read());
    EXPECT_FALSE(d.cu16.q42.read());
    EXPECT_FALSE(d.select36.read());
    EXPECT_TRUE(b.harness.pin35_done.read());
    b.harness.pin29_reset_n.write(true);
    b.at(sc_core::sc_time_stamp() + T);
  });
  EXPECT_EQ(protocol_reports(), 0);
}

TEST(Reset, MidOperationReturnsToIdleAndTheNextOperationIsCorrect) {
  const Config config;
  const Operands aborted = operands(0.6, 2, 255, 0, 0);
  const Operands next = operands(0.97, 150, 30, 60, 90);
  std::vector<sc_time> aborted_starts;
  Result after;
  double cycles_after = 0;
  ProtocolBench& bench = run_scenario(config, [&](ProtocolBench& b) {
    b.harness.reset();
    const sc_time T = b.period();
    // Reset in pass 1 (t0 + 1.25 T) and in pass 2 (t0 + 2.25 T, while 35 is low).
    for (const double reset_at : {1.25, 2.25}) {
      const sc_time t0 = b.rising_edge_from(sc_core::sc_time_stamp() + T);
      b.load(t0 - T / 4, aborted);
      b.start(t0);
      aborted_starts.push_back(t0);
      b.at(t0 + reset_at * T);
      b.harness.pin29_reset_n.write(false);
      b.at(t0 + (reset_at + 1) * T);
      EXPECT_FALSE(b.dut().cu16.q41.read());
      EXPECT_FALSE(b.dut().cu16.q42.read());
      EXPECT_FALSE(b.dut().select36.read()) << "idle during reset";
      b.harness.pin29_reset_n.write(true);
    }
    after = b.harness.run(next);
    cycles_after = b.harness.cycles().front();
  });
  EXPECT_EQ(reports(report::reset_mid_operation), 2);
  EXPECT_EQ(protocol_reports(), 2);
  // Neither aborted operation reached 35↑ at its t0 + 2.5 T.
  for (const auto& d : bench.done)
    for (const sc_time& t0 : aborted_starts) EXPECT_NE(d.time, t0 + 2.5 * bench.period());
  expect_matches_reference(config, next, after);
  EXPECT_DOUBLE_EQ(cycles_after, 2.5) << "the next operation keeps the spec's timing";
}

// Functional coverage (issue 37): the protocol bench records a reset that meets an
// operation in flight (twice in the test above: in pass 1 and in pass 2), and not one
// held while the device is idle (run as children with the recording on).
TEST(ResetRecording, OnlyAResetDuringAnOperationHitsItsBin) {
  using testing_support::hits_of_child;
  EXPECT_EQ(hits_of_child("Reset.MidOperationReturnsToIdleAndTheNextOperationIsCorrect")["reset/during_operation"], 2);
  EXPECT_EQ(hits_of_child("Reset.ClearsOnlyTheControlUnit").count("reset/during_operation"), 0u);
}

}  // namespace
}  // namespace specular
