// The done interrupt in its four orders (issue 37, functional coverage's interrupt/ bins):
// enabled (done_irq bound to the platform's line) or masked (left unbound: the SoC's
// interrupt controller does not take it, software polls STATUS.done; the map has no mask
// register of its own) x STATUS.done acknowledged before or after the next START. Two
// operations run on `lt` and on `pin`; docs/tlm.md's interrupt rules are asserted: done_irq
// is a level that follows STATUS.done, rises when an operation ends (lt: START's time +
// 2.5 T), falls when software writes 1 to STATUS.done or when an operation starts; every
// output equals Core's. The TLM bench's Endpoint records the order (tlm_bench.h).
#include <gtest/gtest.h>

#include <map>
#include <ostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "specular/core.h"
#include "support/functional_coverage_child.h"
#include "support/tlm_bench.h"

namespace {

using namespace specular;
using namespace specular::tlm_testing;

enum class Order { acknowledged_before_next_start, acknowledged_after_next_start };

using Param = std::tuple<Kind, bool /*masked*/, Order>;

std::string param_name(const ::testing::TestParamInfo<Param>& info) {
  const auto& [kind, masked, order] = info.param;
  return std::string(to_string(kind)) + (masked ? "_masked_" : "_enabled_") +
         (order == Order::acknowledged_before_next_start ? "acknowledged_before_next_start"
                                                         : "acknowledged_after_next_start");
}

// ctest's test names carry the parameter as gtest prints it: the orders by name.
void PrintTo(Order order, std::ostream* os) {
  *os << (order == Order::acknowledged_before_next_start ? "before" : "after");
}

class InterruptOrders : public ::testing::TestWithParam<Param> {};

TEST_P(InterruptOrders, DoneIrqFollowsStatusDoneInEveryOrder) {
  // (not a structured binding: C++17 lambdas may not capture one)
  const Kind kind = std::get<0>(GetParam());
  const bool masked = std::get<1>(GetParam());
  const Order order = std::get<2>(GetParam());
  const bool before = order == Order::acknowledged_before_next_start;
  const Config config;
  const Core core(config);
  Operands first, second;  // two operations with different results on every channel
  first.cos = 40000;
  first.n = 5;
  first.rgb = {200, 100, 50};
  second.cos = 60000;
  second.n = 30;
  second.rgb = {255, 1, 7};
  std::vector<std::pair<sc_time, bool>> expected;  // the edges docs/tlm.md gives
  run(
      {kind},
      [&](TlmBench& bench) {
        Endpoint& e = bench.at(0);
        const sc_time T = bench.period;
        auto operation = [&](const Operands& op) {
          EXPECT_EQ(e.write(Reg::cos, static_cast<std::uint32_t>(op.cos)), tlm::TLM_OK_RESPONSE);
          EXPECT_EQ(e.write(Reg::n, static_cast<std::uint32_t>(op.n)), tlm::TLM_OK_RESPONSE);
          EXPECT_EQ(e.write(Reg::r, static_cast<std::uint32_t>(op.rgb[0])), tlm::TLM_OK_RESPONSE);
          EXPECT_EQ(e.write(Reg::g, static_cast<std::uint32_t>(op.rgb[1])), tlm::TLM_OK_RESPONSE);
          EXPECT_EQ(e.write(Reg::b, static_cast<std::uint32_t>(op.rgb[2])), tlm::TLM_OK_RESPONSE);
          const bool raised = e.target->done_irq_level();
          const sc_time start = sc_core::sc_time_stamp();
          EXPECT_EQ(e.write(Reg::control, control_bits::start), tlm::TLM_OK_RESPONSE);
          if (kind == Kind::lt) {  // falls at START if still raised, rises 2.5 T later
            if (raised) expected.emplace_back(start, false);
            expected.emplace_back(start + 2.5 * T, true);
          }
          // polled (masked) or after the interrupt (enabled): the START returned at done
          EXPECT_TRUE(e.read(Reg::status) & status_bits::done) << "STATUS.done after the operation";
          EXPECT_TRUE(e.target->done_irq_level()) << "done_irq follows STATUS.done";
          const Result want = core.run(op);
          EXPECT_EQ(e.read(Reg::out_r), static_cast<std::uint32_t>(want.out[0]));
          EXPECT_EQ(e.read(Reg::out_g), static_cast<std::uint32_t>(want.out[1]));
          EXPECT_EQ(e.read(Reg::out_b), static_cast<std::uint32_t>(want.out[2]));
        };
        auto acknowledge = [&] {
          const sc_time at = sc_core::sc_time_stamp();
          EXPECT_EQ(e.write(Reg::status, status_bits::done), tlm::TLM_OK_RESPONSE);
          if (kind == Kind::lt) expected.emplace_back(at, false);
          EXPECT_FALSE(e.read(Reg::status) & status_bits::done) << "STATUS.done after its W1C";
          EXPECT_FALSE(e.target->done_irq_level()) << "done_irq after STATUS.done's W1C";
        };
        operation(first);
        if (before) acknowledge();
        bench.until(sc_core::sc_time_stamp() + 3 * T);
        const sc_time second_start = sc_core::sc_time_stamp();
        operation(second);  // after: this START meets done still raised
        acknowledge();
        bench.until(sc_core::sc_time_stamp() + 3 * T);
        // the edges: rise, fall (the acknowledgement, or the second START), rise, fall
        std::vector<bool> levels;
        for (const auto& edge : e.irq_edges) levels.push_back(edge.second);
        EXPECT_EQ(levels, std::vector<bool>({true, false, true, false}));
        if (kind == Kind::lt) {
          EXPECT_EQ(e.irq_edges, expected);
        } else if (e.irq_edges.size() == 4) {  // pin: the first fall before or at the second START
          if (before) EXPECT_LT(e.irq_edges[1].first, second_start);
          else EXPECT_GE(e.irq_edges[1].first, second_start);
        }
      },
      config, sc_time(10, SC_NS), {}, /*bind_irq=*/!masked);
}

// The Endpoint records each scenario's order (run as a child with the recording on): the
// "before" scenario acknowledges both operations with done raised; the "after" one starts
// the second while the first's done is raised, then acknowledges the second.
TEST(InterruptOrderRecording, EachScenarioHitsItsOwnBins) {
  using testing_support::hits_of_child;
  using testing_support::hits_under;
  for (const bool masked : {false, true})
    for (const bool before : {true, false}) {
      const std::string mask = masked ? "masked" : "enabled";
      const std::string name = "lt_" + mask + (before ? "_acknowledged_before_next_start" : "_acknowledged_after_next_start");
      const auto hits = hits_of_child("EveryOrder/InterruptOrders.DoneIrqFollowsStatusDoneInEveryOrder/" + name);
      const std::string bin = "interrupt/" + mask + "/acknowledged_";
      const std::map<std::string, long> want =
          before ? std::map<std::string, long>{{bin + "before_next_start", 2}}
                 : std::map<std::string, long>{{bin + "after_next_start", 1}, {bin + "before_next_start", 1}};
      EXPECT_EQ(hits_under(hits, "interrupt/"), want) << name;
    }
}

INSTANTIATE_TEST_SUITE_P(
    EveryOrder, InterruptOrders,
    ::testing::Combine(::testing::Values(Kind::lt, Kind::pin, Kind::axi), ::testing::Bool(),
                       ::testing::Values(Order::acknowledged_before_next_start,
                                         Order::acknowledged_after_next_start)),
    param_name);

}  // namespace
