// Timing of the TLM target: `lt` annotates the spec's latency (start → 35↑ = 2.5 clock
// periods; 2 more per further operation of a batch), the `pin` transactor takes
// exactly that on the netlist, done_irq rises when an operation ends, and `lt` under
// temporal decoupling (tlm_quantumkeeper, 1 µs quantum) returns the same bits.
// Every expected time is computed here by hand from the spec's timing table.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "specular/reference.h"
#include "support/tlm_bench.h"

namespace specular {
namespace {

using namespace tlm_testing;
using Edges = std::vector<std::pair<sc_time, bool>>;

sc_time ns(double value) { return sc_time(value, SC_NS); }

TEST(TlmTiming, LtAnnotatesTheSpecLatencyAndRaisesDoneIrq) {
  run(
      {Kind::lt},
      [](TlmBench& b) {
        Endpoint& e = b.at(0);
        sc_time annotated;
        ASSERT_EQ(e.write(Reg::cos, 50000, &annotated), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, sc_core::SC_ZERO_TIME) << "register writes take no time";
        ASSERT_EQ(e.write(Reg::control, control_bits::start, &annotated), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, ns(20)) << "2.5 periods of 8 ns";
        EXPECT_EQ(sc_core::sc_time_stamp(), ns(20)) << "the bench waited the annotation";

        b.until(ns(30));
        ASSERT_EQ(e.write(Reg::status, status_bits::done), tlm::TLM_OK_RESPONSE);  // irq falls

        b.until(ns(40));  // a batch of 10: 2.5 + 2·9 periods = 164 ns
        std::uint32_t cos[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 65536};
        ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), cos, 40, 0,
                              nullptr, 0, &annotated),
                  tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, ns(164));
        EXPECT_EQ(SpecularTarget::latency_cycles(10), 20.5);

        b.until(ns(300));  // done still high: START drops it, the end raises it again
        ASSERT_EQ(e.write(Reg::control, control_bits::start, &annotated), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, ns(20));
        b.until(ns(400));
        const Edges expected = {{ns(20), true},   // end of the first operation
                                {ns(30), false},  // STATUS.done cleared
                                {ns(204), true},  // end of the batch (40 + 164)
                                {ns(300), false},
                                {ns(320), true}};
        EXPECT_EQ(e.irq_edges, expected);
      },
      Config{}, ns(8));
}

// The transactor on the netlist: START issued a quarter period before a rising edge
// starts on that edge, and 35 rises — and b_transport returns — 2.5 periods later.
TEST(TlmTiming, PinTransactorTakesWhatLtAnnotates) {
  std::vector<sc_time> start_edges, done_edges;
  std::vector<sc_time> returned;
  std::vector<double> harness_cycles;
  Edges irq;
  run(
      {Kind::pin},
      [&](TlmBench& b) {
        Endpoint& e = b.at(0);
        // First operation at 0: the transactor resets the control unit first (pin 29
        // low 0–8 ns), then starts at the first rising edge a quarter period later: 16 ns.
        ASSERT_EQ(e.write(Reg::control, control_bits::start), tlm::TLM_OK_RESPONSE);
        returned.push_back(sc_core::sc_time_stamp());
        // Second: issued at 38 ns = 40 − T/4, starts at 40 ns.
        b.until(ns(38));
        ASSERT_EQ(e.write(Reg::cos, 65536), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(e.write(Reg::control, control_bits::start), tlm::TLM_OK_RESPONSE);
        returned.push_back(sc_core::sc_time_stamp());
        harness_cycles = e.pin().harness.cycles();
        // A batch of 10 issued at 118 ns starts at 120 ns; its last result is valid
        // 2.5 + 2·9 = 20.5 periods later (streaming every 2 periods).
        b.until(ns(118));
        std::uint32_t cos[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 65536};
        ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), cos, 40),
                  tlm::TLM_OK_RESPONSE);
        returned.push_back(sc_core::sc_time_stamp());
        b.until(ns(400));
        irq = e.irq_edges;
      },
      Config{}, ns(8),
      [&](TlmBench& b) {  // watch pins 27 and 35
        SpecularPinTarget& t = b.at(0).pin();
        for (int i = 0; i < 12; ++i) {
          wait(t.harness.pin27_start.posedge_event());
          start_edges.push_back(sc_core::sc_time_stamp());
          wait(t.harness.pin35_done.posedge_event());
          done_edges.push_back(sc_core::sc_time_stamp());
          if (i >= 2) break;  // the batch streams: keep the first start only
        }
        for (int i = 0; i < 9; ++i) {
          wait(t.harness.pin35_done.posedge_event());
          done_edges.push_back(sc_core::sc_time_stamp());
        }
      });
  ASSERT_EQ(start_edges.size(), 3u);
  EXPECT_EQ(start_edges[0], ns(16));
  EXPECT_EQ(start_edges[1], ns(40));
  EXPECT_EQ(start_edges[2], ns(120));
  ASSERT_EQ(done_edges.size(), 12u);
  const sc_time lt_latency = ns(8) * SpecularTarget::latency_cycles(1);
  EXPECT_EQ(done_edges[0] - start_edges[0], ns(20));
  EXPECT_EQ(done_edges[1] - start_edges[1], ns(20));
  EXPECT_EQ(lt_latency, ns(20));
  ASSERT_EQ(returned.size(), 3u);
  EXPECT_EQ(returned[0], ns(36)) << "b_transport returns at 35↑";
  EXPECT_EQ(returned[1], ns(60)) << "start edge 40 ns + 2.5 periods";
  EXPECT_EQ(returned[1] - start_edges[1], lt_latency) << "what lt annotates";
  EXPECT_EQ(returned[2], ns(120 + 164)) << "batch: 20.5 periods, as lt annotates";
  EXPECT_EQ(returned[2] - start_edges[2], ns(8) * SpecularTarget::latency_cycles(10));
  for (int i = 2; i < 12; ++i)
    EXPECT_EQ(done_edges[i], ns(120 + 20 + 16 * (i - 2))) << "result " << i - 2;
  ASSERT_EQ(harness_cycles.size(), 1u);
  EXPECT_EQ(harness_cycles[0], 2.5);
  // done_irq: high at 35↑ of each operation, low from the next start request.
  const Edges expected = {{ns(36), true}, {ns(38), false}, {ns(60), true},
                          {ns(118), false}, {ns(284), true}};
  EXPECT_EQ(irq, expected);
}

// Temporal decoupling: the initiator runs ahead of simulated time by up to 1 µs and
// synchronises once per quantum; the bits equal the pin transactor's (run in a
// second thread without decoupling), and total time is 2.5 periods per operation.
TEST(TlmTiming, LtUnderAQuantumKeeperGivesTheSameBits) {
  constexpr int operations = 2000;
  std::vector<Operands> ops;
  std::mt19937_64 random(7);
  std::uniform_int_distribution<code_t> cos(0, 65536), n(1, 1000), rgb(0, 255);
  for (int i = 0; i < operations; ++i) {
    Operands op;
    op.cos = cos(random);
    op.n = n(random);
    op.rgb = {rgb(random), rgb(random), rgb(random)};
    ops.push_back(op);
  }
  std::vector<std::array<std::int32_t, 3>> lt, pin;
  std::vector<sc_time> sync_times;
  sc_time ahead_max, total;
  run(
      {Kind::lt, Kind::pin},
      [&](TlmBench& b) {
        tlm::tlm_global_quantum::instance().set(sc_time(1, sc_core::SC_US));
        Endpoint& e = b[Kind::lt];
        e.keeper.reset();
        for (const Operands& op : ops) {
          lt.push_back(e.driver.compute(op));
          if (e.keeper.get_local_time() > ahead_max) ahead_max = e.keeper.get_local_time();
          if (sync_times.empty() || sync_times.back() != sc_core::sc_time_stamp())
            sync_times.push_back(sc_core::sc_time_stamp());
        }
        e.keeper.sync();
        total = sc_core::sc_time_stamp();
      },
      Config{}, ns(10),
      [&](TlmBench& b) {
        for (const Operands& op : ops) pin.push_back(b[Kind::pin].driver.compute(op));
      });
  ASSERT_EQ(lt.size(), ops.size());
  ASSERT_EQ(pin.size(), ops.size());
  const Formats f{Widths{}};
  for (int i = 0; i < operations; ++i) {
    ASSERT_EQ(lt[i], pin[i]) << "operation " << i;
    const unsigned n_i = static_cast<unsigned>(ops[i].n);
    const double k = reference::k(n_i, Normalisation::patent);
    const std::array<double, 3> intensity{double(ops[i].rgb[0]), double(ops[i].rgb[1]),
                                          double(ops[i].rgb[2])};
    const reference::Figures ref = reference::evaluate(
        f.cos.to_real(ops[i].cos), n_i, intensity, Normalisation::patent, Saturation::clamp, 16);
    for (int ch = 0; ch < 3; ++ch)
      ASSERT_NEAR(f.out.to_real(lt[i][ch]), ref.out_ref[ch],
                  reference::out_tolerance(k, intensity[ch], f.out.lsb()));
  }
  // 2000 operations × 25 ns = 50 µs, in 50 quanta of 1 µs.
  EXPECT_EQ(total, sc_time(50, sc_core::SC_US));
  EXPECT_GT(ahead_max, ns(900)) << "the initiator ran ahead of the kernel";
  EXPECT_LE(ahead_max, sc_time(1, sc_core::SC_US));
  EXPECT_LE(sync_times.size(), 51u) << "one synchronisation per quantum";
  for (const sc_time& t : sync_times)
    EXPECT_EQ(t.value() % sc_time(1, sc_core::SC_US).value(), 0u) << t;
}

}  // namespace
}  // namespace specular
