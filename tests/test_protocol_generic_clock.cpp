// The protocol checker when pin 28 is not an sc_clock (a user's own clock signal):
// it measures the period from the edges, and notices a missing or stopped clock.
// The clock here rises at k·T for k ≥ 1 (T = 10 ns) until `clock_stop`.
#include <gtest/gtest.h>

#include <functional>
#include <utility>
#include <vector>

#include "specular/core.h"
#include "specular/device.h"
#include "support/protocol_bench.h"

namespace specular {
namespace {

using namespace protocol_testing;
using sc_core::sc_time;
using sc_core::SC_NS;

const sc_time T(10, SC_NS);

class GenericClockBench : public sc_core::sc_module {
 public:
  using Scenario = std::function<void(GenericClockBench&)>;

  GenericClockBench(sc_core::sc_module_name name, const sc_time& clock_stop, Scenario scenario)
      : sc_module(name), clock_stop_(clock_stop), scenario_(std::move(scenario)) {
    SPECULAR_HAS_PROCESS(GenericClockBench);
    dut.pin17_cos(pin17);  dut.pin18_n(pin18);  dut.pin19_h(pin19);  dut.pin20_a(pin20);
    dut.pin21_r(pin21);    dut.pin22_g(pin22);  dut.pin23_b(pin23);
    dut.pin24_r(pin24);    dut.pin25_g(pin25);  dut.pin26_b(pin26);
    dut.pin27_start(pin27);  dut.pin28_clk(pin28);  dut.pin29_reset_n(pin29);
    dut.pin30_load_n(pin30); dut.pin31_load_r(pin31); dut.pin32_load_g(pin32);
    dut.pin33_load_b(pin33); dut.pin34_carry(pin34); dut.pin35_done(pin35);
    pin19.write(dut.constant_h19());
    pin20.write(dut.constant_a20());
    SC_THREAD(drive_clock);
    SC_THREAD(run);
    SC_METHOD(on_done);
    sensitive << pin35.posedge_event();
    dont_initialize();
  }

  bus_signal pin17{"pin17"}, pin18{"pin18"}, pin19{"pin19"}, pin20{"pin20"};
  bus_signal pin21{"pin21"}, pin22{"pin22"}, pin23{"pin23"};
  bus_signal pin24{"pin24"}, pin25{"pin25"}, pin26{"pin26"};
  wire pin27{"pin27"}, pin28{"pin28"}, pin29{"pin29", true};
  wire pin30{"pin30"}, pin31{"pin31"}, pin32{"pin32"}, pin33{"pin33"};
  wire pin34{"pin34", true}, pin35{"pin35", true};
  SpecularDevice dut{"dut"};
  std::vector<std::pair<sc_time, std::array<code_t, 3>>> done;

  void at(const sc_time& when) {
    if (when > sc_core::sc_time_stamp()) wait(when - sc_core::sc_time_stamp());
  }
  void pulse(wire& w, const sc_time& when, const sc_time& width) {
    at(when);
    w.write(true);
    wait(width);
    w.write(false);
  }
  void reset(const sc_time& when) {
    at(when);
    pin29.write(false);
    wait(T);
    pin29.write(true);
  }
  /// Operands on the pins and strobes 30–33 at `when` for a quarter period.
  void load(const sc_time& when, const Operands& op) {
    at(when);
    pin17.write(op.cos);
    pin18.write(op.n);
    pin21.write(op.rgb[0]);
    pin22.write(op.rgb[1]);
    pin23.write(op.rgb[2]);
    for (wire* w : {&pin30, &pin31, &pin32, &pin33}) w->write(true);
    wait(T / 4);
    for (wire* w : {&pin30, &pin31, &pin32, &pin33}) w->write(false);
  }

 private:
  void drive_clock() {
    for (sc_time edge = T; edge <= clock_stop_; edge += T / 2) {
      at(edge);
      pin28.write(!pin28.read());
    }
  }
  void run() {
    scenario_(*this);
    sc_core::sc_stop();
  }
  void on_done() {
    done.push_back({sc_core::sc_time_stamp(), {pin24.read(), pin25.read(), pin26.read()}});
  }

  sc_time clock_stop_;
  Scenario scenario_;
};

GenericClockBench& run_generic(const sc_time& clock_stop, GenericClockBench::Scenario scenario) {
  static GenericClockBench* bench = nullptr;  // outlives sc_start, as SystemC wants
  bench = new GenericClockBench("bench", clock_stop, std::move(scenario));
  sc_core::sc_start();
  return *bench;
}

void expect_outputs(const Operands& in, const std::array<code_t, 3>& got) {
  Result r;
  r.out = got;
  const Config config;
  const Formats formats(config.widths);
  const double cos_q = formats.cos.to_real(in.cos);
  const unsigned n = static_cast<unsigned>(in.n);
  const std::array<double, 3> rgb{double(in.rgb[0]), double(in.rgb[1]), double(in.rgb[2])};
  const auto ref = reference::evaluate(cos_q, n, rgb, config.normalisation, config.saturation,
                                       config.widths.cos_frac_bits);
  const double k = reference::k(n, config.normalisation);
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(formats.out.to_real(got[ch]), ref.out_ref[ch],
                reference::out_tolerance(k, rgb[ch], formats.out.lsb()));
}

TEST(ProtocolGenericClock, MeasuresThePeriodAndChecksLikeWithAnScClock) {
  const Operands op = Core(Config{}).operands(0.9, 17, 40, 50, 60);
  GenericClockBench& bench = run_generic(sc_time(400, SC_NS), [&](GenericClockBench& b) {
    b.reset(T / 4);
    // Legal: start at 5 T on a rising edge, result at 7.5 T.
    b.load(5 * T - T / 4, op);
    b.pulse(b.pin27, 5 * T, T / 2);
    // A start exactly at a falling edge (10.5 T).
    b.pulse(b.pin27, 10.5 * T, T / 4);
    // Too soon: 20 T, then 21.75 T (less than 2 T).
    b.pulse(b.pin27, 20 * T, T / 2);
    b.pulse(b.pin27, 21.75 * T, T / 8);
    b.at(30 * T);
  });
  EXPECT_EQ(reports(report::start_at_falling_edge), 1);
  EXPECT_EQ(reports(report::start_too_soon), 1);
  EXPECT_EQ(protocol_reports(), 2);
  ASSERT_FALSE(bench.done.empty());
  EXPECT_EQ(bench.done.front().first, 7.5 * T);
  expect_outputs(op, bench.done.front().second);
}

TEST(ProtocolGenericClock, StartWithoutAnyClockIsReported) {
  GenericClockBench& bench = run_generic(sc_core::SC_ZERO_TIME, [&](GenericClockBench& b) {
    b.dut.protocol_checker.set_no_clock_timeout(20 * T);
    b.reset(T / 4);
    b.load(3 * T - T / 4, Core(Config{}).operands(0.9, 17, 40, 50, 60));
    b.pulse(b.pin27, 3 * T, T / 2);
    b.at(40 * T);
  });
  EXPECT_EQ(reports(report::no_clock), 1);
  EXPECT_EQ(protocol_reports(), 1);
  EXPECT_TRUE(bench.done.empty());
}

TEST(ProtocolGenericClock, ClockStoppingMidOperationIsReported) {
  // The clock stops high at 6 T, after pass 1 (start at 5 T): the operation never ends.
  GenericClockBench& bench = run_generic(6 * T, [&](GenericClockBench& b) {
    b.reset(T / 4);
    b.load(5 * T - T / 4, Core(Config{}).operands(0.9, 17, 40, 50, 60));
    b.pulse(b.pin27, 5 * T, T / 2);
    b.at(20 * T);
  });
  EXPECT_EQ(reports(report::no_done), 1);
  EXPECT_EQ(protocol_reports(), 1);
  EXPECT_TRUE(bench.done.empty());
}

}  // namespace
}  // namespace specular
