// The one place that knows how to run operations on each model of the device.
//
// Adding a model (e.g. the TLM one) means one enum value, one name in
// model_names(), and one case in run_operations().
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "specular/core.h"
#include "specular/energy/energy_meter.h"

namespace specular {
namespace tb {

enum class Model {
  pin,   ///< the pin-level SystemC netlist, driven through PinHarness (default)
  core,  ///< the kernel-free bit-accurate core; latency annotated from the spec
  tlm,   ///< the TLM-2.0 `lt` target through its registers; cycles = its annotation
  rtl,   ///< the verilated RTL twin (rtl/, twin/) driven through the same harness as `pin`
  rtl_sync,  ///< the synchronous variant (rtl/device/specular_device_sync.v), its own protocol
  /// A design variant's C++ model (issue 26, RunSettings::variant): kernel-free, no
  /// clock (cycles 0). Chosen by specular_tb --variant NAME, never by --model.
  variant,
};

const char* to_string(Model model);
/// "pin", "core", "tlm", "rtl" or "rtl-sync"; throws UsageError naming the value and the choices.
Model parse_model(const std::string& text);
/// "pin, core, tlm, rtl, rtl-sync": the choices, for messages and --help.
std::string model_names();
/// Whether the model runs on pins 17–35 under DeviceHarness (pin, rtl, rtl-sync).
bool pin_level(Model model);

/// The spec's timing table: start → rising edge of 35 in clock periods. The core
/// model has no clock; it reports this as its annotated latency.
constexpr double spec_latency_cycles = 2.5;
/// The synchronous variant's timing table (docs/rtl.md): start edge → 35↑.
constexpr double sync_latency_cycles = 2.0;
/// The latency a model must show: sync_latency_cycles for rtl-sync, else the spec's
/// (Model::variant: none is checked, its C++ model has no clock).
double latency_cycles(Model model);

/// How to run: which model, the device's configuration, the clock, tracing.
struct RunSettings {
  Model model = Model::pin;
  Config config{};
  std::string variant;  ///< Model::variant: the registered name (variant.h)
  std::uint64_t clock_period_ps = 10000;  ///< pin, rtl: period of pin 28; tlm: of its annotation
  std::string vcd_base;          ///< pin, rtl: VCD file name without ".vcd"; empty = no trace
  /// rtl, rtl-sync: ".fst" has Verilator write FST directly (the twins verilated with
  /// --trace-fst) into vcd_base + ".fst", windows and replays included; else ".vcd".
  std::string twin_trace_suffix = ".vcd";
  bool real_views = false;       ///< with a trace: add the *_real views (RealView)
  std::size_t chunk_size = 4096;  ///< operations per batch (memory stays flat)
  /// With vcd_base: trace only operations [trace_first, trace_first + trace_count)
  /// (indices from 0 over the run), opened as the first one's pins are driven and
  /// closed at the last one's 35↑; the instants between are those of a whole-run trace.
  bool trace_window = false;
  std::uint64_t trace_first = 0, trace_count = 0;
  /// Pin-level models: after each batch's sink, which of its operations (indices over
  /// the run) to run again with a trace, each with the two before it (the first of
  /// them untraced, to set the device's state), into the file base it names
  /// (specular_tb --trace-failures). Empty: nothing is replayed.
  std::function<std::vector<std::pair<std::uint64_t, std::string>>()> replays;
  /// tlm (issue 61): the power trace's window, and what each window gives: its end
  /// (ns), its mean power (mW), the energy so far (pJ). Empty: no power trace (unless
  /// vcd_base asks for the target's view, which holds it).
  std::uint64_t power_window_ps = 1000000;
  std::function<void(double end_ns, double power_mw, double energy_pj)> power_window;
  /// tlm: the target's energy tally once the run is over.
  std::function<void(const energy::EnergyTally&)> tlm_energy;
};

/// Replaces `chunk` with up to `max` next operations; returns false when none are left.
using OperandSource = std::function<bool(std::vector<Operands>& chunk, std::size_t max)>;
/// Receives each batch: operands, the results (codes), and cycles (start → 35↑).
using ResultSink = std::function<void(const std::vector<Operands>& chunk,
                                      const std::vector<Result>& results,
                                      const std::vector<double>& cycles)>;

/// Runs every operation `source` yields on the chosen model, in batches of at most
/// `settings.chunk_size`, handing each batch's results to `sink` in order.
/// The pin model elaborates a design and runs the SystemC kernel, which can be done
/// once per process. Exceptions from `source` or `sink` propagate to the caller.
void run_operations(const RunSettings& settings, const OperandSource& source,
                    const ResultSink& sink);

/// Convenience form for a list that fits in memory.
void run_operations(const RunSettings& settings, const std::vector<Operands>& operations,
                    std::vector<Result>& results, std::vector<double>& cycles);

}  // namespace tb
}  // namespace specular
