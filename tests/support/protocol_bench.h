// A bench for the protocol tests (test_protocol_*, test_power_on_*, test_misuse_*):
// a PinHarness plus a scenario thread that may also drive the pins directly, off the
// protocol, and a monitor that records every result the device signals on pin 35.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "functional_coverage.h"
#include "specular/pin_harness.h"
#include "specular/twin/rtl_device.h"
#include "specular/reference.h"
#include "specular/report_ids.h"

namespace specular {
namespace protocol_testing {

using sc_core::sc_time;
using sc_core::SC_NS;

/// How many reports of `type` the report handler has seen (SystemC counts per type).
inline int reports(const char* type) { return sc_core::sc_report_handler::get_count(type); }

/// Every protocol report, all types together.
inline int protocol_reports() {
  int total = 0;
  for (const char* type : report::protocol_types) total += reports(type);
  return total;
}

/// Generic over the harness: PinHarness (the SystemC netlist) or RtlHarness (the
/// RTL twin), so that the misuse tests run against both devices.
template <class Harness>
class ProtocolBenchT : public sc_core::sc_module {
 public:
  using Scenario = std::function<void(ProtocolBenchT&)>;

  struct Done {
    sc_time time;
    Result pins;  ///< register 9, ROM 38, multiplier 39, pins 24–26 at the rising edge of 35
  };

  ProtocolBenchT(sc_core::sc_module_name name, const Config& config, Scenario scenario,
                const sc_time& period = sc_time(10, SC_NS))
      : sc_module(name), harness("harness", config, period), scenario_(std::move(scenario)) {
    SPECULAR_HAS_PROCESS(ProtocolBenchT);
    SC_THREAD(run);
    SC_METHOD(on_done);
    sensitive << harness.pin35_done.posedge_event();
    dont_initialize();
    SC_METHOD(on_control_pins);
    sensitive << harness.pin27_start.posedge_event() << harness.pin29_reset_n.negedge_event();
    dont_initialize();
  }

  Harness harness;
  std::vector<Done> done;  ///< every rising edge of 35, in order

  const sc_time& period() const { return harness.clock_period(); }
  auto& dut() { return harness.dut; }

  /// Wait until absolute time `when` (no-op if it has passed).
  void at(const sc_time& when) {
    const sc_time now = sc_core::sc_time_stamp();
    if (when > now) wait(when - now);
  }
  /// The first rising clock edge at or after `when` (the harness clock rises at k·T).
  sc_time rising_edge_from(const sc_time& when) const {
    return period() * std::ceil(when / period());
  }
  /// Put operands on pins 17, 18, 21–23 and pulse strobes 30–33 at `when`, for a
  /// quarter period (what PinHarness does before a start).
  void load(const sc_time& when, const Operands& op) {
    at(when);
    harness.pin17_cos.write(op.cos);
    harness.pin18_n.write(op.n);
    harness.pin21_r.write(op.rgb[0]);
    harness.pin22_g.write(op.rgb[1]);
    harness.pin23_b.write(op.rgb[2]);
    for (wire* strobe : strobes()) strobe->write(true);
    wait(period() / 4);
    for (wire* strobe : strobes()) strobe->write(false);
  }
  /// Strobes 30–33 and start rising at the same instant `when` (registers 2, 10–12
  /// take the new operands at the start edge itself).
  void load_and_start(const sc_time& when, const Operands& op) {
    at(when);
    harness.pin17_cos.write(op.cos);
    harness.pin18_n.write(op.n);
    harness.pin21_r.write(op.rgb[0]);
    harness.pin22_g.write(op.rgb[1]);
    harness.pin23_b.write(op.rgb[2]);
    for (wire* strobe : strobes()) strobe->write(true);
    harness.pin27_start.write(true);
    wait(period() / 4);
    for (wire* strobe : strobes()) strobe->write(false);
    wait(period() / 4);
    harness.pin27_start.write(false);
  }
  /// Pulse one strobe (30–33) high at `when` for `width`.
  void pulse(wire& signal, const sc_time& when, const sc_time& width) {
    at(when);
    signal.write(true);
    wait(width);
    signal.write(false);
  }
  /// Start (pin 27) high at `when` for `width` (half a period by default).
  void start(const sc_time& when, sc_time width = sc_core::SC_ZERO_TIME) {
    if (width == sc_core::SC_ZERO_TIME) width = period() / 2;
    pulse(harness.pin27_start, when, width);
  }

 private:
  std::vector<wire*> strobes() {
    return {&harness.pin30_load_n, &harness.pin31_load_r, &harness.pin32_load_g,
            &harness.pin33_load_b};
  }
  void run() {
    scenario_(*this);
    sc_core::sc_stop();
  }
  // Functional coverage (issue 37): pin 29 falling while an operation is in flight (a
  // start rose since the last rising edge of 35) hits reset/during_operation.
  void on_control_pins() {
    if (harness.pin27_start.posedge() && harness.pin29_reset_n.read()) in_flight_ = true;
    if (harness.pin29_reset_n.negedge()) {
      if (in_flight_) testing_support::coverage::record_reset_during_operation();
      in_flight_ = false;
    }
  }
  bool in_flight_ = false;

  void on_done() {
    in_flight_ = false;
    Result r;
    r.reg9_pass2 = harness.dut.reg9_q.read();
    r.rom38_k = harness.dut.rom38_k.read();
    r.norm39 = harness.dut.mul39_norm.read();
    r.out = {harness.pin24_r.read(), harness.pin25_g.read(), harness.pin26_b.read()};
    done.push_back({sc_core::sc_time_stamp(), r});
  }

  Scenario scenario_;
};

using ProtocolBench = ProtocolBenchT<PinHarness>;
using RtlProtocolBench = ProtocolBenchT<RtlHarness>;

/// Elaborate a bench, run the scenario to its end, and return the bench for checks.
/// (One elaboration per test process: call once per TEST.)
template <class Harness = PinHarness>
ProtocolBenchT<Harness>& run_scenario(const Config& config,
                                      typename ProtocolBenchT<Harness>::Scenario scenario) {
  static ProtocolBenchT<Harness>* bench = nullptr;  // lives until the process ends, as SystemC wants
  bench = new ProtocolBenchT<Harness>("bench", config, std::move(scenario));
  sc_core::sc_start();
  return *bench;
}

/// Checks a result against the double reference within the project's tolerances
/// (reference.h), as the testbench's scoreboard does.
inline void expect_matches_reference(const Config& config, const Operands& in, const Result& got) {
  const Formats formats(config.widths);
  const double cos_q = formats.cos.to_real(in.cos);
  const unsigned n = static_cast<unsigned>(in.n);
  const std::array<double, 3> rgb{double(in.rgb[0]), double(in.rgb[1]), double(in.rgb[2])};
  const reference::Figures ref = reference::evaluate(cos_q, n, rgb, config.normalisation,
                                                     config.saturation, config.widths.cos_frac_bits);
  const double k = reference::k(n, config.normalisation);
  EXPECT_NEAR(formats.norm.to_real(got.norm39), ref.norm_ref, reference::norm_tolerance(k))
      << "cos " << cos_q << " n " << n;
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(formats.out.to_real(got.out[ch]), ref.out_ref[ch],
                reference::out_tolerance(k, rgb[ch], formats.out.lsb()))
        << "channel " << ch << ", cos " << cos_q << " n " << n;
}

}  // namespace protocol_testing
}  // namespace specular
