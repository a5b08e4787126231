// A harness around the pin-level device: clock, pin signals, wired constants, and a
// bus-functional driver that runs operations with the spec's protocol.
#pragma once

#include <cstddef>
#include <vector>

#include "specular/device.h"
#include "specular/systemc.h"

namespace specular {

/// Owns the device, its clock (pin 28) and every pin signal, ties pins 19, 20, 34 to
/// their constants, and drives operations exactly as spec §3 "protocol" allows:
///   - pin 17 and, when they change, registers 2 and 10–12 (strobes 30–33) are set a
///     quarter period before the start edge; strobes fall at the start edge;
///   - start (27) rises with a rising clock edge and falls half a period later;
///   - results are read at the rising edge of 35 (start + 2.5 T);
///   - starts come every 2 T while n, R, G, B are unchanged (only cos λ streams),
///     every 3 T when they change (they may be reloaded only after 35 rises).
/// The run functions block: call them from an SC_THREAD.
class PinHarness : public sc_core::sc_module {
 public:
  PinHarness(sc_core::sc_module_name name, const Config& config,
             const sc_core::sc_time& clock_period, bool real_views = false);

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

  const sc_core::sc_time& clock_period() const { return period_; }

 private:
  void on_select36();  // pass 1 is in register 9 while select 36 rises
  void on_done35();    // results are valid at the rising edge of 35
  void wait_until(const sc_core::sc_time& when);

  sc_core::sc_time period_;

 public:
  sc_core::sc_clock pin28_clk;
  bus_signal pin17_cos{"pin17_cos"};
  bus_signal pin18_n{"pin18_n"};
  bus_signal pin19_h{"pin19_h"};
  bus_signal pin20_a{"pin20_a"};
  bus_signal pin21_r{"pin21_r"};
  bus_signal pin22_g{"pin22_g"};
  bus_signal pin23_b{"pin23_b"};
  bus_signal pin24_r{"pin24_r"};
  bus_signal pin25_g{"pin25_g"};
  bus_signal pin26_b{"pin26_b"};
  wire pin27_start{"pin27_start"};
  wire pin29_reset_n{"pin29_reset_n", true};
  wire pin30_load_n{"pin30_load_n"};
  wire pin31_load_r{"pin31_load_r"};
  wire pin32_load_g{"pin32_load_g"};
  wire pin33_load_b{"pin33_load_b"};
  wire pin34_carry{"pin34_carry", true};
  wire pin35_done{"pin35_done", true};
  SpecularDevice dut;

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

}  // namespace specular
