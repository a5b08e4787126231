// Control unit 16 inside the device (Fig. 1 + Fig. 2), driven pin by pin by this test
// (not by PinHarness): back-to-back operations at the minimum start interval of the
// spec's protocol Decision (2T), reset (pin 29) in the middle of an operation, and
// start while reset is held. Results are checked against the double reference.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "specular/device.h"
#include "specular/reference.h"
#include "support/signal_log.h"

namespace specular {
namespace {

using sc_core::sc_time;
using testing_support::SignalLog;

/// The device with its own clock and pin signals, a logic analyser on the control
/// nets, monitors that sample register 9 when select 36 rises (pass 1 written) and the
/// result pins when 35 rises, and a script thread.
class DeviceBench : public sc_core::sc_module {
 public:
  struct Sample {
    sc_time time;
    code_t reg1, reg9, norm;
    std::array<code_t, 3> out;
  };

  DeviceBench(sc_core::sc_module_name name, const sc_time& period, const Config& config = Config{})
      : sc_module(name),
        period(period),
        clk("pin28_clk", period, 0.5, sc_core::SC_ZERO_TIME, true),
        dut("dut", config),
        log("log", {{"q41", &dut.cu16.q41},
                    {"q42", &dut.cu16.q42},
                    {"select36", &dut.select36},
                    {"write37", &dut.write37},
                    {"done35", &pin35_done}}) {
    SPECULAR_HAS_PROCESS(DeviceBench);
    dut.pin17_cos(pin17_cos);
    dut.pin18_n(pin18_n);
    dut.pin19_h(pin19_h);
    dut.pin20_a(pin20_a);
    dut.pin21_r(pin21_r);
    dut.pin22_g(pin22_g);
    dut.pin23_b(pin23_b);
    dut.pin24_r(pin24_r);
    dut.pin25_g(pin25_g);
    dut.pin26_b(pin26_b);
    dut.pin27_start(pin27_start);
    dut.pin28_clk(clk);
    dut.pin29_reset_n(pin29_reset_n);
    dut.pin30_load_n(pin30_load_n);
    dut.pin31_load_r(pin31_load_r);
    dut.pin32_load_g(pin32_load_g);
    dut.pin33_load_b(pin33_load_b);
    dut.pin34_carry(pin34_carry);
    dut.pin35_done(pin35_done);
    // Wired constants (spec §2): ½ on pin 19, 1.0 on pin 20, both in the formats the
    // design note gives (U10.1 and S14.22), written here from those formats.
    pin19_h.write(std::llround(std::ldexp(0.5, dut.formats().mux4.frac_bits)));
    pin20_a.write(std::llround(std::ldexp(1.0, dut.formats().reg9.frac_bits)));

    SC_THREAD(run_script);
    SC_METHOD(drive_start);
    sensitive << start_event_;
    dont_initialize();
    SC_METHOD(on_pass1);
    sensitive << dut.select36.posedge_event();
    dont_initialize();
    SC_METHOD(on_done);
    sensitive << pin35_done.posedge_event();
    dont_initialize();
  }

  void wait_until(const sc_time& t) {
    if (t > sc_core::sc_time_stamp()) wait(t - sc_core::sc_time_stamp());
  }
  /// Registers 2 and 10–12 for a start at t: data and strobes up at t − 3T/8 (after
  /// the previous operation's 35↑ at t − T/2 when starts are 3T apart), strobes down
  /// at t − T/8.
  void load_before(const sc_time& t, code_t n, const std::array<code_t, 3>& rgb) {
    wait_until(t - period * 0.375);
    pin18_n.write(n);
    pin21_r.write(rgb[0]);
    pin22_g.write(rgb[1]);
    pin23_b.write(rgb[2]);
    for (wire* strobe : {&pin30_load_n, &pin31_load_r, &pin32_load_g, &pin33_load_b}) strobe->write(true);
    wait_until(t - period * 0.125);
    for (wire* strobe : {&pin30_load_n, &pin31_load_r, &pin32_load_g, &pin33_load_b}) strobe->write(false);
  }
  /// cos λ on pin 17 a sixteenth of a period before t; start (27) rises at t, a rising
  /// clock edge, and falls half a period later. Returns at t.
  void start_at(const sc_time& t, code_t cos) {
    wait_until(t - period / 16);
    pin17_cos.write(cos);
    wait_until(t);
    start_event_.notify();
  }

  const sc_time period;
  sc_core::sc_clock clk;
  bus_signal pin17_cos{"pin17_cos"}, pin18_n{"pin18_n"}, pin19_h{"pin19_h"},
      pin20_a{"pin20_a"}, pin21_r{"pin21_r"}, pin22_g{"pin22_g"}, pin23_b{"pin23_b"},
      pin24_r{"pin24_r"}, pin25_g{"pin25_g"}, pin26_b{"pin26_b"};
  wire pin27_start{"pin27_start"}, pin29_reset_n{"pin29_reset_n", true},
      pin30_load_n{"pin30_load_n"}, pin31_load_r{"pin31_load_r"}, pin32_load_g{"pin32_load_g"},
      pin33_load_b{"pin33_load_b"}, pin34_carry{"pin34_carry", true},
      pin35_done{"pin35_done", true};
  SpecularDevice dut;
  SignalLog log;
  std::function<void(DeviceBench&)> script;
  std::vector<Sample> pass1, results;

 private:
  void run_script() {
    // Power-on reset, as a user's SoC does first: pin 29 low from T/4 to 5T/4.
    wait_until(period / 4);
    pin29_reset_n.write(false);
    wait_until(period * 1.25);
    pin29_reset_n.write(true);
    if (script) script(*this);
    sc_core::sc_stop();
  }
  void drive_start() {
    const bool rising = !pin27_start.read();
    pin27_start.write(rising);
    if (rising) start_event_.notify(period / 2);
  }
  Sample sample() const {
    return {sc_core::sc_time_stamp(), dut.reg1_q.read(), dut.reg9_q.read(), dut.mul39_norm.read(),
            {pin24_r.read(), pin25_g.read(), pin26_b.read()}};
  }
  void on_pass1() { pass1.push_back(sample()); }
  void on_done() { results.push_back(sample()); }
  sc_core::sc_event start_event_{"start_event"};
};

/// One operation's expected figures, from the double reference.
struct Expected {
  code_t cos;
  unsigned n;
  std::array<code_t, 3> rgb;
};

void expect_matches_reference(const DeviceBench& bench, const DeviceBench::Sample& got,
                              const Expected& e) {
  const Formats& f = bench.dut.formats();
  const Config& c = bench.dut.config();
  const double cos_q = std::ldexp(static_cast<double>(e.cos), -f.widths.cos_frac_bits);
  const std::array<double, 3> rgb = {double(e.rgb[0]), double(e.rgb[1]), double(e.rgb[2])};
  const auto ref = reference::evaluate(cos_q, e.n, rgb, c.normalisation, c.saturation,
                                       f.widths.cos_frac_bits);
  const double kn = reference::k(e.n, c.normalisation);
  SCOPED_TRACE("cos code " + std::to_string(e.cos) + ", n " + std::to_string(e.n) + ", at " +
               got.time.to_string());
  EXPECT_NEAR(f.reg9.to_real(got.reg9), ref.approx_ref, reference::approx_tolerance());
  EXPECT_NEAR(f.norm.to_real(got.norm), ref.norm_ref, reference::norm_tolerance(kn));
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(f.out.to_real(got.out[ch]), ref.out_ref[ch],
                reference::out_tolerance(kn, rgb[ch], f.out.lsb()))
        << "channel " << ch;
}

/// Register 9 after pass 1 against 1 − n·log2 cos λ (n half-LSBs of ROM 5's word, plus
/// multiplier 6's rounding; 2^-10 is far looser and enough to tell the passes apart).
void expect_pass1(const DeviceBench& bench, const DeviceBench::Sample& got, const Expected& e) {
  const Formats& f = bench.dut.formats();
  const double cos_q = std::ldexp(static_cast<double>(e.cos), -f.widths.cos_frac_bits);
  const double want = 1.0 - e.n * reference::log2_cos(cos_q, f.widths.cos_frac_bits);
  EXPECT_NEAR(f.reg9.to_real(got.reg9), want, std::ldexp(1.0, -10)) << "pass 1, cos code " << e.cos;
  // At 35↑ register 1 may already hold the next operation's cos λ (back to back).
  EXPECT_EQ(got.reg1, e.cos) << "register 1 holds the cos λ of this operation during pass 1";
}

// Two operations 2T apart with the same n and RGB (only cos λ changes): both results
// are right, and every edge of the second is the first's shifted by exactly 2T.
TEST(ControlProtocol, BackToBackAtTheMinimumStartInterval) {
  const sc_time T(10, sc_core::SC_NS);
  DeviceBench bench("bench", T);
  const std::array<code_t, 3> rgb = {200, 100, 50};
  const std::vector<Expected> ops = {{60000, 37, rgb}, {64000, 37, rgb}};
  const sc_time s0 = T * 3;
  bench.script = [&](DeviceBench& b) {
    b.load_before(s0, 37, rgb);
    b.start_at(s0, ops[0].cos);
    b.start_at(s0 + T * 2, ops[1].cos);
    b.wait_until(s0 + T * 8);
  };
  sc_core::sc_start();

  ASSERT_EQ(bench.results.size(), 2u);
  ASSERT_EQ(bench.pass1.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    expect_pass1(bench, bench.pass1[i], ops[i]);
    expect_matches_reference(bench, bench.results[i], ops[i]);
  }
  // 35 rises at 5T/2 after each start (spec: start → 35↑ = 2.5 periods).
  EXPECT_EQ(bench.results[0].time, s0 + T * 2.5);
  EXPECT_EQ(bench.results[1].time, s0 + T * 4.5);
  // Each control net's edges: the second operation's are the first's + 2T.
  for (const char* net : {"q41", "q42", "select36", "write37", "done35"}) {
    for (bool value : {true, false}) {
      const auto edges = bench.log.edges(net, value);
      ASSERT_EQ(edges.size() % 2, 0u) << net;
      const std::size_t half = edges.size() / 2;
      ASSERT_GT(half, 0u) << net;
      for (std::size_t i = 0; i < half; ++i)
        EXPECT_EQ(edges[half + i] - edges[i], T * 2) << net << (value ? " rise " : " fall ") << i;
    }
  }
  EXPECT_EQ(bench.log.rises("write37"),
            (std::vector<sc_time>{s0 + T, s0 + T * 2, s0 + T * 3, s0 + T * 4}));
  EXPECT_EQ(bench.log.falls("done35"), (std::vector<sc_time>{s0 + T * 2, s0 + T * 4}));
}

// A stream of 40 operations every 2T, cos λ random (0, 1.0 and the last codes below
// 1.0 included), under several n: every result right, every 35↑ at start + 2.5T.
TEST(ControlProtocol, StreamOfOperationsEveryTwoPeriods) {
  const sc_time T(8, sc_core::SC_NS);
  DeviceBench bench("bench", T);
  std::mt19937 random(2024);
  std::vector<Expected> ops;
  std::vector<sc_time> starts;
  sc_time t = T * 2;
  for (unsigned n : {1u, 64u, 1000u}) {
    const std::array<code_t, 3> rgb = {std::uniform_int_distribution<code_t>(0, 255)(random),
                                       std::uniform_int_distribution<code_t>(0, 255)(random), 255};
    t += T;  // reload: the next start 3T after the previous one
    for (code_t cos : {code_t{0}, code_t{65536}, code_t{65535}, code_t{65534}}) {
      ops.push_back({cos, n, rgb});
      starts.push_back(t);
      t += T * 2;
    }
    for (int i = 0; i < 10; ++i) {
      ops.push_back({std::uniform_int_distribution<code_t>(0, 65536)(random), n, rgb});
      starts.push_back(t);
      t += T * 2;
    }
  }
  bench.script = [&](DeviceBench& b) {
    for (std::size_t i = 0; i < ops.size(); ++i) {
      if (i == 0 || ops[i].n != ops[i - 1].n) b.load_before(starts[i], ops[i].n, ops[i].rgb);
      b.start_at(starts[i], ops[i].cos);
    }
    b.wait_until(starts.back() + T * 4);
  };
  sc_core::sc_start();

  ASSERT_EQ(bench.results.size(), ops.size());
  ASSERT_EQ(bench.pass1.size(), ops.size());
  for (std::size_t i = 0; i < ops.size(); ++i) {
    expect_pass1(bench, bench.pass1[i], ops[i]);
    expect_matches_reference(bench, bench.results[i], ops[i]);
    EXPECT_EQ(bench.results[i].time, starts[i] + T * 2.5) << "operation " << i;
  }
  EXPECT_EQ(bench.log.rises("write37").size(), 2 * ops.size()) << "two writes per operation";
}

// Reset (pin 29 low) in the middle of an operation, at T/4, 3T/4, 5T/4, 7T/4 and 9T/4
// after start: Q41..Q43 clear, no further write to register 9, and no result, except
// at 9T/4: pass 2 was written at 2T, and clearing Q43 ends 35's low pulse early, so
// 35 rises at the reset with the aborted operation's (complete) result. The next
// operation (other operands) is right and on time.
TEST(ControlProtocol, ResetInTheMiddleOfAnOperation) {
  const sc_time T(10, sc_core::SC_NS);
  DeviceBench bench("bench", T);
  const std::vector<int> quarters = {1, 3, 5, 7, 9};
  const Expected aborted = {40000, 3, {255, 255, 255}};
  std::vector<Expected> next_ops;
  for (int i = 0; i < 5; ++i) next_ops.push_back({code_t{62000 + 700 * i}, unsigned(10 + 200 * i), {9, 99, 199}});
  struct AtReset {
    sc_time reset_at, next_start;
    bool q41, q42, q43;
    code_t reg9_after_reset, reg9_before_next;
    std::size_t results_before_reset, results_before_next;
  };
  std::vector<AtReset> cases;
  bench.script = [&](DeviceBench& b) {
    sc_time t = T * 2;
    for (std::size_t i = 0; i < quarters.size(); ++i) {
      AtReset c;
      b.load_before(t, aborted.n, aborted.rgb);
      b.start_at(t, aborted.cos);
      c.reset_at = t + T * (quarters[i] / 4.0);
      b.wait_until(c.reset_at);
      c.results_before_reset = b.results.size();
      b.pin29_reset_n.write(false);
      b.wait_until(c.reset_at + T / 8);
      c.q41 = b.dut.cu16.q41.read();
      c.q42 = b.dut.cu16.q42.read();
      c.q43 = b.dut.select36.read();
      c.reg9_after_reset = b.dut.reg9_q.read();
      b.wait_until(c.reset_at + T);
      b.pin29_reset_n.write(true);
      c.next_start = T * std::ceil((c.reset_at + T * 1.25) / T);
      b.load_before(c.next_start, next_ops[i].n, next_ops[i].rgb);
      b.wait_until(c.next_start - T / 8);
      c.reg9_before_next = b.dut.reg9_q.read();
      c.results_before_next = b.results.size();
      b.start_at(c.next_start, next_ops[i].cos);
      b.wait_until(c.next_start + T * 3);
      cases.push_back(c);
      t = c.next_start + T * 4;
    }
  };
  sc_core::sc_start();

  ASSERT_EQ(cases.size(), quarters.size());
  ASSERT_EQ(bench.results.size(), quarters.size() + 1);  // + the early 35↑ at 9T/4
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const AtReset& c = cases[i];
    SCOPED_TRACE("reset at start + " + std::to_string(quarters[i]) + "·T/4");
    EXPECT_FALSE(c.q41);
    EXPECT_FALSE(c.q42);
    EXPECT_FALSE(c.q43);
    EXPECT_EQ(c.reg9_before_next, c.reg9_after_reset) << "register 9 written after reset";
    const bool pass2_done = quarters[i] > 8;
    ASSERT_EQ(c.results_before_next, c.results_before_reset + (pass2_done ? 1 : 0));
    if (pass2_done) {
      const auto& early = bench.results[c.results_before_reset];
      EXPECT_EQ(early.time, c.reset_at) << "35 rises with the reset";
      expect_matches_reference(bench, early, aborted);
    }
    for (const sc_time& w : bench.log.rises("write37"))
      EXPECT_FALSE(w > c.reset_at && w < c.next_start) << "write pulse at " << w;
    for (const sc_time& d : bench.log.falls("done35"))
      EXPECT_FALSE(d > c.reset_at && d < c.next_start) << "35 fell at " << d;
    const auto& next = bench.results[c.results_before_next];
    expect_matches_reference(bench, next, next_ops[i]);
    EXPECT_EQ(next.time, c.next_start + T * 2.5);
  }
}

// Start while reset is held low: nothing happens (no write, no done); after release
// the next operation is right.
TEST(ControlProtocol, StartWithResetHeldLowDoesNothing) {
  const sc_time T(10, sc_core::SC_NS);
  DeviceBench bench("bench", T);
  const Expected op = {50000, 20, {10, 20, 30}};
  const sc_time s0 = T * 3, s1 = T * 10;
  code_t reg9_before = 0, reg9_after = 0;
  bench.script = [&](DeviceBench& b) {
    b.load_before(s0, op.n, op.rgb);
    b.pin29_reset_n.write(false);
    reg9_before = b.dut.reg9_q.read();
    b.start_at(s0, op.cos);
    b.wait_until(s0 + T * 5.25);
    reg9_after = b.dut.reg9_q.read();
    b.pin29_reset_n.write(true);
    b.start_at(s1, op.cos);
    b.wait_until(s1 + T * 4);
  };
  sc_core::sc_start();
  EXPECT_EQ(reg9_after, reg9_before);
  for (const char* net : {"q41", "q42", "select36", "write37"})
    for (const sc_time& t : bench.log.rises(net)) EXPECT_GE(t, s1) << net << " rose during reset";
  EXPECT_EQ(bench.log.falls("done35"), std::vector<sc_time>{s1 + T * 2});
  ASSERT_EQ(bench.results.size(), 1u);
  expect_matches_reference(bench, bench.results[0], op);
  EXPECT_EQ(bench.results[0].time, s1 + T * 2.5);
}

}  // namespace
}  // namespace specular
