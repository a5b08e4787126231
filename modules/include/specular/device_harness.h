/// \file
/// A harness around a pin-level device: clock, pin signals, wired constants, and a
/// bus-functional driver that runs operations with the spec's protocol.
///
/// Generic over the device it drives: the SystemC netlist (SpecularDevice, aliased
/// PinHarness in pin_harness.h) or the verilated RTL twin behind its port adapter
/// (twin/: RtlHarness). A Device provides pins 17–35 as bus_in/bus_out/wire_in/wire_out
/// ports, the nets the monitor samples (select36, reg1_q, reg9_q, rom38_k, mul39_norm),
/// formats(), constant_h19(), constant_a20(), trace(file), and a constructor
/// (name, Config, bool real_views). A device that samples its inputs as levels at the
/// rising clock edge (the synchronous variant, twin/: RtlSyncDevice) says so with
/// `static constexpr bool synchronous = true;` and is driven with its own protocol.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "specular/core.h"
#include "specular/real_view.h"
#include "specular/systemc.h"

namespace specular {

/// Whether a device samples start (27) and the loads (30–33) as levels at the rising
/// clock edge (`Device::synchronous`), instead of taking their edges as Fig. 1–2 do.
template <class Device, class = void>
struct is_synchronous_device : std::false_type {};
/// A device that declares `static constexpr bool synchronous` is what that constant says.
template <class Device>
struct is_synchronous_device<Device, std::void_t<decltype(Device::synchronous)>>
    : std::bool_constant<Device::synchronous> {};

/// How a DeviceHarness runs pin 28. Either freely from time 0 (an sc_clock: the
/// testbench, the benches) or on demand (a TLM transactor, SpecularPinTarget): then it
/// rises only between clock_on() and a few periods after clock_off(), on the same grid of
/// rising edges (multiples of the period), so an idle device costs no process
/// activations and sc_start() without a time end returns when nothing else is pending.
enum class ClockMode : std::uint8_t {
  free_running,  ///< an sc_clock from time 0
  on_demand      ///< only between clock_on() and clock_off() (plus idle_tail_rises)
};

/// Owns the device, its clock (pin 28) and every pin signal, ties pins 19,
/// 20, 34 to their constants, and drives operations exactly as spec §3 "protocol" allows:
///   - pin 17 and, when they change, registers 2 and 10–12 (strobes 30–33) are set a
///     quarter period before the start edge; strobes fall at the start edge;
///   - start (27) rises with a rising clock edge and falls half a period later;
///   - results are read at the rising edge of 35 (start + 2.5 T);
///   - starts come every 2 T while n, R, G, B are unchanged (only cos λ streams),
///     every 3 T when they change (they may be reloaded only after 35 rises).
///
/// A synchronous device (is_synchronous_device) gets its protocol instead
/// (docs/rtl.md): start, pin 17 and the loads with their data rise a quarter period
/// before the start edge and start and the loads fall a quarter period after it;
/// results are read at 35↑ (start + 2 T); the same 2 T and 3 T intervals.
/// The run functions block: call them from an SC_THREAD. Pin 28 runs as ClockMode says.
///
/// \tparam Device the device driven (see this file's description for what it provides)
template <class Device>
class DeviceHarness : public sc_core::sc_module {
 public:
  /// Builds the device as `dut` with `config` (and `real_views`, see SpecularDevice),
  /// its clock of period `clock_period` in `clock_mode`, and binds every pin.
  DeviceHarness(sc_core::sc_module_name name, const Config& config,
                const sc_core::sc_time& clock_period, bool real_views = false,
                ClockMode clock_mode = ClockMode::free_running);

  /// On demand: let pin 28 run (from the next rising edge of the grid). Call before
  /// reset() or a run; free-running: nothing to do.
  void clock_on();
  /// On demand: stop pin 28, low, after `idle_tail_rises` more rising edges (the
  /// control unit settles back to idle). Free-running: nothing to do.
  void clock_off();
  /// Rising edges of an on-demand pin 28 so far (0 when free-running).
  std::uint64_t clock_rises() const { return clock_rises_; }
  /// Rising edges an on-demand pin 28 still makes after clock_off().
  static constexpr int idle_tail_rises = 3;
  /// Pin 28, whichever the mode.
  const sc_core::sc_signal_in_if<bool>& pin28() const { return *pin28_; }

  /// Pulse reset (pin 29) low for one clock period; the control unit returns to idle.
  void reset();
  /// One operation; returns what registers 1, 9, ROM 38, multiplier 39 and pins 24–26
  /// held, as the monitor sampled them.
  Result run(const Operands& in);
  /// Many operations, pipelined as the protocol allows. `out` is resized to match.
  void run_batch(const std::vector<Operands>& in, std::vector<Result>& out);
  /// Clock periods from the start edge to the rising edge of 35, per operation of the
  /// last batch (2.5 by the spec's timing table).
  const std::vector<double>& cycles() const { return cycles_; }

  /// Trace pins (under this harness's name) and the device's internals.
  void trace(sc_core::sc_trace_file* file) const;

  /// The period of pin 28, T.
  const sc_core::sc_time& clock_period() const { return period_; }

  /// Called (if set) with an operation's index in its batch just before its pins are
  /// driven: where a trace window opens (`specular_tb --trace-ops`). Empty: nothing is
  /// called.
  std::function<void(std::size_t)> before_drive, after_done;
  /// \var after_done
  /// Called (if set) with an operation's index in its batch just after its results were
  /// taken at 35↑: where a trace window closes. Empty: nothing is called.

 private:
  void on_select36();  // pass 1 is in register 9 while select 36 rises
  void on_done35();    // results are valid at the rising edge of 35
  void wait_until(const sc_core::sc_time& when);
  void tick_clock();  // on demand: the next edge of pin 28

  sc_core::sc_time period_;
  ClockMode clock_mode_;
  std::unique_ptr<sc_core::sc_clock> free_clock_;  ///< pin 28, free-running
  std::unique_ptr<wire> gated_clock_;              ///< pin 28, on demand
  const sc_core::sc_signal_in_if<bool>* pin28_ = nullptr;
  sc_core::sc_event clock_event_;
  bool clock_wanted_ = false;
  bool clock_running_ = false;
  int tail_rises_ = 0;
  std::uint64_t clock_rises_ = 0;

 public:
  bus_signal pin17_cos{"pin17_cos"};          ///< pin 17: cos λ code
  bus_signal pin18_n{"pin18_n"};              ///< pin 18: n code
  bus_signal pin19_h{"pin19_h"};              ///< pin 19: tied to the constant h
  bus_signal pin20_a{"pin20_a"};              ///< pin 20: tied to the constant a
  bus_signal pin21_r{"pin21_r"};              ///< pin 21: R intensity
  bus_signal pin22_g{"pin22_g"};              ///< pin 22: G intensity
  bus_signal pin23_b{"pin23_b"};              ///< pin 23: B intensity
  bus_signal pin24_r{"pin24_r"};              ///< pin 24: specular R (output)
  bus_signal pin25_g{"pin25_g"};              ///< pin 25: specular G (output)
  bus_signal pin26_b{"pin26_b"};              ///< pin 26: specular B (output)
  wire pin27_start{"pin27_start"};            ///< pin 27: write register 1 and start
  wire pin29_reset_n{"pin29_reset_n", true};  ///< pin 29: reset, active low (high: running)
  wire pin30_load_n{"pin30_load_n"};          ///< pin 30: write register 2
  wire pin31_load_r{"pin31_load_r"};          ///< pin 31: write register 10
  wire pin32_load_g{"pin32_load_g"};          ///< pin 32: write register 11
  wire pin33_load_b{"pin33_load_b"};          ///< pin 33: write register 12
  wire pin34_carry{"pin34_carry", true};      ///< pin 34: adder 8's carry-in, tied to 1
  wire pin35_done{"pin35_done", true};        ///< pin 35: done (active-low pulse; idle high)
  Device dut;                                 ///< the device driven

 private:
  // Monitor state for the batch in flight.
  std::vector<Result>* batch_out_ = nullptr;
  std::vector<sc_core::sc_time> start_times_;
  std::vector<double> cycles_;
  std::size_t pass1_seen_ = 0;
  std::size_t done_seen_ = 0;
  std::size_t started_ = 0;
  sc_core::sc_event result_event_;
  bool loaded_ = false;
  Operands loaded_operands_;
};

// ---- implementation (a template: instantiated once per device, see pin_harness.cpp) ----

template <class Device>
DeviceHarness<Device>::DeviceHarness(sc_core::sc_module_name name, const Config& config,
                                     const sc_core::sc_time& clock_period, bool real_views,
                                     ClockMode clock_mode)
    : sc_module(name),
      period_(clock_period),
      clock_mode_(clock_mode),
      free_clock_(clock_mode == ClockMode::free_running
                      ? std::make_unique<sc_core::sc_clock>("pin28_clk", clock_period, 0.5,
                                                            sc_core::SC_ZERO_TIME, true)
                      : nullptr),
      gated_clock_(clock_mode == ClockMode::on_demand ? std::make_unique<wire>("pin28_clk") : nullptr),
      dut("dut", config, real_views) {
  SPECULAR_HAS_PROCESS(DeviceHarness);
  if (free_clock_) {
    pin28_ = free_clock_.get();
    dut.pin28_clk(*free_clock_);
  } else {
    pin28_ = gated_clock_.get();
    dut.pin28_clk(*gated_clock_);
    SC_METHOD(tick_clock);
    sensitive << clock_event_;
    dont_initialize();
  }
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
  dut.pin29_reset_n(pin29_reset_n);
  dut.pin30_load_n(pin30_load_n);
  dut.pin31_load_r(pin31_load_r);
  dut.pin32_load_g(pin32_load_g);
  dut.pin33_load_b(pin33_load_b);
  dut.pin34_carry(pin34_carry);
  dut.pin35_done(pin35_done);
  // Pins 19 and 20 carry the constants h and a (½ and 1.0 under the patent's constants).
  pin19_h.write(dut.constant_h19());
  pin20_a.write(dut.constant_a20());

  SC_METHOD(on_select36);
  sensitive << dut.select36.posedge_event();
  dont_initialize();
  SC_METHOD(on_done35);
  sensitive << pin35_done.posedge_event();
  dont_initialize();
}

template <class Device>
void DeviceHarness<Device>::wait_until(const sc_core::sc_time& when) {
  const sc_core::sc_time now = sc_core::sc_time_stamp();
  if (when > now) wait(when - now);
}

template <class Device>
void DeviceHarness<Device>::clock_on() {
  clock_wanted_ = true;
  tail_rises_ = 0;
  if (clock_mode_ != ClockMode::on_demand || clock_running_) return;
  clock_running_ = true;
  // Resume on the free-running clock's grid: the next rising edge at a multiple of T.
  const sc_core::sc_time now = sc_core::sc_time_stamp();
  clock_event_.notify(period_ * std::ceil(now / period_) - now);
}

template <class Device>
void DeviceHarness<Device>::clock_off() {
  clock_wanted_ = false;
  tail_rises_ = 0;
}

template <class Device>
void DeviceHarness<Device>::tick_clock() {
  const bool rise = !gated_clock_->read();
  if (!rise && !clock_wanted_ && tail_rises_ >= idle_tail_rises) {
    gated_clock_->write(false);
    clock_running_ = false;  // stopped low: nothing more is scheduled
    return;
  }
  gated_clock_->write(rise);
  if (rise) {
    ++clock_rises_;
    if (!clock_wanted_) ++tail_rises_;
  }
  const sc_core::sc_time high = period_ / 2;
  clock_event_.notify(rise ? high : period_ - high);
}

template <class Device>
void DeviceHarness<Device>::reset() {
  // Release a quarter period after an edge: never on an edge (no race with the clock).
  pin29_reset_n.write(false);
  wait(period_);
  pin29_reset_n.write(true);
  loaded_ = false;
}

template <class Device>
void DeviceHarness<Device>::on_select36() {
  if (batch_out_ == nullptr || pass1_seen_ >= started_) return;
  Result& r = (*batch_out_)[pass1_seen_++];
  r.reg1 = dut.reg1_q.read();
  r.reg9_pass1 = dut.reg9_q.read();
}

template <class Device>
void DeviceHarness<Device>::on_done35() {
  if (batch_out_ == nullptr || done_seen_ >= started_) return;
  Result& r = (*batch_out_)[done_seen_];
  r.reg9_pass2 = dut.reg9_q.read();
  r.rom38_k = dut.rom38_k.read();
  r.norm39 = dut.mul39_norm.read();
  r.out = {pin24_r.read(), pin25_g.read(), pin26_b.read()};
  cycles_[done_seen_] = (sc_core::sc_time_stamp() - start_times_[done_seen_]) / period_;
  ++done_seen_;
  result_event_.notify(sc_core::SC_ZERO_TIME);
  if (after_done) after_done(done_seen_ - 1);
}

template <class Device>
Result DeviceHarness<Device>::run(const Operands& in) {
  std::vector<Result> out;
  run_batch({in}, out);
  return out.front();
}

template <class Device>
void DeviceHarness<Device>::run_batch(const std::vector<Operands>& in, std::vector<Result>& out) {
  using sc_core::sc_time;
  const std::size_t count = in.size();
  out.assign(count, Result{});
  start_times_.assign(count, sc_time());
  cycles_.assign(count, 0.0);
  batch_out_ = &out;
  pass1_seen_ = done_seen_ = started_ = 0;

  const sc_time quarter = period_ / 4;
  // The first start edge: the next rising edge at least a quarter period from now.
  const sc_time now = sc_core::sc_time_stamp();
  sc_time start = period_ * std::ceil((now + quarter) / period_);
  for (std::size_t i = 0; i < count; ++i) {
    const Operands& op = in[i];
    const bool reload = !loaded_ || op.n != loaded_operands_.n || op.rgb != loaded_operands_.rgb;
    if (i > 0) {
      const sc_time earliest = start_times_[i - 1] + period_ * (reload ? 3 : 2);
      if (start < earliest) start = earliest;
    }
    wait_until(start - quarter);
    if (before_drive) before_drive(i);
    pin17_cos.write(op.cos);
    if constexpr (is_synchronous_device<Device>::value) pin27_start.write(true);
    if (reload) {
      pin18_n.write(op.n);
      pin21_r.write(op.rgb[0]);
      pin22_g.write(op.rgb[1]);
      pin23_b.write(op.rgb[2]);
      pin30_load_n.write(true);
      pin31_load_r.write(true);
      pin32_load_g.write(true);
      pin33_load_b.write(true);
      loaded_operands_ = op;
      loaded_ = true;
    }
    wait_until(start);
    start_times_[i] = start;
    ++started_;
    if constexpr (is_synchronous_device<Device>::value) {
      // Levels held a quarter period past the edge that samples them.
      wait(quarter);
    }
    pin30_load_n.write(false);
    pin31_load_r.write(false);
    pin32_load_g.write(false);
    pin33_load_b.write(false);
    if constexpr (is_synchronous_device<Device>::value) {
      pin27_start.write(false);
    } else {
      pin27_start.write(true);
      wait(period_ / 2);
      pin27_start.write(false);
    }
  }
  while (done_seen_ < count) wait(result_event_);
  batch_out_ = nullptr;
}

template <class Device>
void DeviceHarness<Device>::trace(sc_core::sc_trace_file* file) const {
  const std::string scope = std::string(name()) + ".";
  const Formats& f = dut.formats();
  const std::pair<const bus_signal*, const FixedFormat*> buses[] = {
      {&pin17_cos, &f.cos}, {&pin18_n, &f.n},   {&pin19_h, &f.mux4}, {&pin20_a, &f.reg9},
      {&pin21_r, &f.rgb},   {&pin22_g, &f.rgb}, {&pin23_b, &f.rgb},     {&pin24_r, &f.out},
      {&pin25_g, &f.out},   {&pin26_b, &f.out}};
  for (const auto& [bus, format] : buses)
    trace_bus(file, *bus, *format, scope + bus->basename());
  for (const wire* w : {&pin27_start, &pin29_reset_n, &pin30_load_n, &pin31_load_r,
                        &pin32_load_g, &pin33_load_b, &pin34_carry, &pin35_done})
    sc_core::sc_trace(file, *w, scope + w->basename());
  sc_core::sc_trace(file, *pin28_, scope + "pin28_clk");
  dut.trace(file);
}

}  // namespace specular
