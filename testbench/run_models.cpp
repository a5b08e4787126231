#include "run_models.h"

#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include <tlm_utils/simple_initiator_socket.h>

#include "specular/pin_harness.h"
#ifdef SPECULAR_HAS_RTL_TWIN
#include "specular/twin/rtl_device.h"
#include "specular/twin/rtl_sync_device.h"
#endif
#include "specular/tlm/driver.h"
#include "specular/tlm/lt_target.h"
#include "specular/variants/variant.h"
#include "usage_error.h"

namespace specular {
namespace tb {

const char* to_string(Model model) {
  switch (model) {
    case Model::pin: return "pin";
    case Model::core: return "core";
    case Model::tlm: return "tlm";
    case Model::rtl: return "rtl";
    case Model::rtl_sync: return "rtl-sync";
    case Model::variant: return "variant";
  }
  return "?";
}

std::string model_names() { return "pin, core, tlm, rtl, rtl-sync"; }

bool pin_level(Model model) {
  return model == Model::pin || model == Model::rtl || model == Model::rtl_sync;
}

double latency_cycles(Model model) {
  return model == Model::rtl_sync ? sync_latency_cycles : spec_latency_cycles;
}

Model parse_model(const std::string& text) {
  if (text == "pin") return Model::pin;
  if (text == "core") return Model::core;
  if (text == "tlm") return Model::tlm;
#ifdef SPECULAR_HAS_RTL_TWIN
  if (text == "rtl") return Model::rtl;
  if (text == "rtl-sync") return Model::rtl_sync;
#else
  if (text == "rtl" || text == "rtl-sync")
    throw UsageError("--model " + text + ": this specular_tb was built without the RTL twin "
                     "(configured with -DSPECULAR_BUILD_RTL=OFF); the choices here: pin, core, tlm");
#endif
  throw UsageError("--model = '" + text + "' is not one of: " + model_names());
}

namespace {

/// SystemC prints its reports on standard output, where they would break a CSV or
/// JSON report: warnings and errors go to standard error instead, and the kernel's
/// informational chatter ("simulation stopped by user", …) is dropped.
void kernel_reports_to_stderr(const sc_core::sc_report& report, const sc_core::sc_actions& actions) {
  if (report.get_severity() == sc_core::SC_INFO) return;
  if (actions & sc_core::SC_DISPLAY)
    std::cerr << sc_core::sc_report_compose_message(report) << std::endl;
  sc_core::sc_report_handler::default_handler(report, actions & ~sc_core::SC_DISPLAY);
}

/// SystemC's VCD writer dumps a file's initial values without a time: a viewer puts
/// them at 0. A file opened during the run gets "#T" before them, T its first instant.
void stamp_initial_values(const std::string& path, std::uint64_t ps) {
  if (ps == 0) return;
  const std::string stamped = path + ".stamped";
  {
    std::ifstream in(path, std::ios::binary);
    std::ofstream out(stamped, std::ios::binary | std::ios::trunc);
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("$dumpvars", 0) == 0) {
        out << '#' << ps << '\n' << line << '\n';
        break;
      }
      out << line << '\n';
    }
    if (in.peek() != std::char_traits<char>::eof()) out << in.rdbuf();
    if (!out) throw std::runtime_error("cannot write the trace '" + path + "' (disk full?)");
  }
  if (std::rename(stamped.c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot write the trace '" + path + "'");
}

/// A trace file opened and closed during the simulation: the SystemC netlist's
/// through SystemC's VCD writer, the twins' through Verilator's (RtlDeviceBase).
template <class Harness>
class Tracer {
 public:
  Tracer(Harness& harness, const std::string& twin_suffix) : harness_(harness), twin_suffix_(twin_suffix) {}
  ~Tracer() {
    try {
      close();
    } catch (...) {  // a trace left open by a failed run: its error was reported
    }
  }
  /// Before sc_start: every trace will come during the simulation.
  void prepare() {
#ifdef SPECULAR_HAS_RTL_TWIN
    if constexpr (!std::is_same_v<Harness, PinHarness>) harness_.dut.allow_tracing(twin_suffix_ == ".fst");
#endif
  }
  /// `base`: the file name without ".vcd".
  void open(const std::string& base) {
    if (open_) return;
    open_ = true;
#ifdef SPECULAR_HAS_RTL_TWIN
    if constexpr (!std::is_same_v<Harness, PinHarness>) {
      harness_.dut.open_vcd(base + twin_suffix_);
      return;
    }
#endif
    path_ = base + ".vcd";
    opened_ps_ = sc_core::sc_time_stamp().value();
    vcd_ = sc_core::sc_create_vcd_trace_file(base.c_str());
    vcd_->set_time_unit(1, sc_core::SC_PS);
    harness_.trace(vcd_);
  }
  void close() {
    if (!open_) return;
    open_ = false;
#ifdef SPECULAR_HAS_RTL_TWIN
    if constexpr (!std::is_same_v<Harness, PinHarness>) {
      harness_.dut.close_vcd();
      return;
    }
#endif
    sc_core::sc_close_vcd_trace_file(vcd_);
    vcd_ = nullptr;
    stamp_initial_values(path_, opened_ps_);
  }
  bool is_open() const { return open_; }

 private:
  Harness& harness_;
  std::string twin_suffix_;  ///< ".vcd" or ".fst" (RunSettings::twin_trace_suffix)
  sc_core::sc_trace_file* vcd_ = nullptr;
  bool open_ = false;
  std::string path_;
  std::uint64_t opened_ps_ = 0;
};

/// The bus-functional side of the pin model and the RTL twin: an SC_THREAD that
/// resets the device, then feeds it batch after batch through the harness and stops
/// the kernel. It opens and closes a trace window (--trace-ops) and replays failing
/// operations into their own traces (--trace-failures).
template <class Harness>
class PinDriver : public sc_core::sc_module {
 public:
  PinDriver(sc_core::sc_module_name name, Harness& harness, const OperandSource& source,
            const ResultSink& sink, const RunSettings& settings)
      : sc_module(name), harness_(harness), source_(source), sink_(sink), settings_(settings),
        tracer_(harness, settings.twin_trace_suffix) {
    SPECULAR_HAS_PROCESS(PinDriver);
    SC_THREAD(drive);
    SC_METHOD(close_window);
    sensitive << close_event_;
    dont_initialize();
    if (window()) {
      tracer_.prepare();
      harness_.before_drive = [this](std::size_t i) {
        if (base_ + i == settings_.trace_first) tracer_.open(settings_.vcd_base);
      };
      harness_.after_done = [this](std::size_t i) {
        if (base_ + i + 1 == settings_.trace_first + settings_.trace_count)
          close_event_.notify(harness_.clock_period() / 4);
      };
    } else if (settings_.replays) {
      tracer_.prepare();
    }
  }

  /// What went wrong inside the thread (a sink that cannot write, …), rethrown by
  /// run_operations once the kernel has stopped.
  std::exception_ptr failure;

 private:
  bool window() const { return !settings_.vcd_base.empty() && settings_.trace_window; }

  void close_window() { tracer_.close(); }

  void drive() {
    try {
      harness_.reset();
      std::vector<Operands> chunk;
      std::vector<Result> results;
      chunk.reserve(settings_.chunk_size);
      while (source_(chunk, settings_.chunk_size)) {
        harness_.run_batch(chunk, results);
        sink_(chunk, results, harness_.cycles());
        if (settings_.replays) replay(chunk);
        base_ += chunk.size();
        // The operations before the next batch, for a replay of its first ones.
        previous_.assign(chunk.size() >= 2 ? chunk.end() - 2 : chunk.begin(), chunk.end());
      }
      if (tracer_.is_open()) {  // the window reached past the last operation
        wait(harness_.clock_period() / 4);
        tracer_.close();
      }
    } catch (...) {
      failure = std::current_exception();
    }
    sc_core::sc_stop();
  }

  /// Runs each requested operation k again, after k−2 (untraced: it leaves the
  /// device's registers as they were), with k−1 and k traced, in the batches they had
  /// (a batch boundary between them gives the same gap as in the run). From k ≤ 1 the
  /// replay starts with a reset, as the run did.
  void replay(const std::vector<Operands>& chunk) {
    const auto requests = settings_.replays();
    if (requests.empty()) return;
    const auto saved_before = harness_.before_drive;
    const auto saved_after = harness_.after_done;
    harness_.after_done = nullptr;
    std::vector<Result> results;
    for (const auto& [k, file_base] : requests) {
      if (k < base_ || k >= base_ + chunk.size()) continue;
      const std::uint64_t from = k >= 2 ? k - 2 : 0;
      if (from == 0) harness_.reset();
      const std::uint64_t traced_from = k >= 1 ? k - 1 : 0;
      std::vector<Operands> before, within;  // from the batch before this one, from this one
      std::uint64_t before_first = 0;
      for (std::uint64_t j = from; j <= k; ++j) {
        if (j >= base_) {
          within.push_back(chunk[j - base_]);
        } else if (base_ - j <= previous_.size()) {
          if (before.empty()) before_first = j;
          before.push_back(previous_[previous_.size() - (base_ - j)]);
        }
      }
      if (!before.empty()) run_traced(before, before_first, traced_from, file_base, results);
      run_traced(within, from > base_ ? from : base_, traced_from, file_base, results);
      wait(harness_.clock_period() / 4);
      tracer_.close();
    }
    harness_.before_drive = saved_before;
    harness_.after_done = saved_after;
  }

  /// One batch of a replay: operations [first, first + batch.size()), the trace
  /// opened before `traced_from`'s pins are driven.
  void run_traced(const std::vector<Operands>& batch, std::uint64_t first,
                  std::uint64_t traced_from, const std::string& file_base,
                  std::vector<Result>& results) {
    harness_.before_drive = [&, first, traced_from](std::size_t i) {
      if (first + i == traced_from) tracer_.open(file_base);
    };
    harness_.run_batch(batch, results);
  }

  Harness& harness_;
  const OperandSource& source_;
  const ResultSink& sink_;
  const RunSettings& settings_;
  Tracer<Harness> tracer_;
  sc_core::sc_event close_event_;
  std::uint64_t base_ = 0;           ///< index of the batch's first operation in the run
  std::vector<Operands> previous_;   ///< the last operations of the batch before
};

/// Both pin-level models: the SystemC netlist (PinHarness) and the RTL twin
/// (RtlHarness), under the same harness, driver and trace settings.
template <class Harness>
void run_on_pins(const RunSettings& settings, const OperandSource& source,
                 const ResultSink& sink) {
  sc_core::sc_report_handler::set_handler(kernel_reports_to_stderr);
  const bool whole_run = !settings.vcd_base.empty() && !settings.trace_window;
  const bool tracing = !settings.vcd_base.empty() || settings.replays;
  const sc_core::sc_time period(static_cast<double>(settings.clock_period_ps), sc_core::SC_PS);
  // Real-valued views cost a process activation per bus change, and GTKWave shows the
  // code buses as fixed point anyway (waveforms/specular.gtkw): only when asked for.
  Harness harness("tb", settings.config, period, tracing && settings.real_views);
  PinDriver<Harness> driver("driver", harness, source, sink, settings);
#ifdef SPECULAR_HAS_RTL_TWIN
  // The twin's waveform is Verilator's own, of the RTL's nets (waveforms/specular_rtl.gtkw).
  if constexpr (std::is_same_v<Harness, RtlHarness> || std::is_same_v<Harness, RtlSyncHarness>) {
    if (whole_run) harness.dut.open_vcd(settings.vcd_base + settings.twin_trace_suffix);
    sc_core::sc_start();
    if (driver.failure) std::rethrow_exception(driver.failure);
    return;
  }
#endif

  sc_core::sc_trace_file* vcd = nullptr;
  if (whole_run) {
    vcd = sc_core::sc_create_vcd_trace_file(settings.vcd_base.c_str());
    vcd->set_time_unit(1, sc_core::SC_PS);
    harness.trace(vcd);
  }
  sc_core::sc_start();
  if (vcd != nullptr) sc_core::sc_close_vcd_trace_file(vcd);
  if (driver.failure) std::rethrow_exception(driver.failure);
}

void run_core_model(const RunSettings& settings, const OperandSource& source,
                    const ResultSink& sink) {
  const Core core(settings.config);
  std::vector<Operands> chunk;
  std::vector<Result> results;
  std::vector<double> cycles;
  chunk.reserve(settings.chunk_size);
  while (source(chunk, settings.chunk_size)) {
    results.resize(chunk.size());
    for (std::size_t i = 0; i < chunk.size(); ++i) results[i] = core.run(chunk[i]);
    cycles.assign(chunk.size(), spec_latency_cycles);  // annotated, not measured
    sink(chunk, results, cycles);
  }
}

/// A design variant's C++ model (issue 26): the lobe on multiplier 39's bus, pins
/// 24–26, register 1 as loaded; it has no passes, ROM 38 word or clock (all 0).
void run_variant_model(const RunSettings& settings, const OperandSource& source,
                       const ResultSink& sink) {
  const std::unique_ptr<variants::Variant> variant = variants::make_variant(settings.variant, settings.config);
  std::vector<Operands> chunk;
  std::vector<Result> results;
  std::vector<double> cycles;
  chunk.reserve(settings.chunk_size);
  while (source(chunk, settings.chunk_size)) {
    results.assign(chunk.size(), Result{});
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      const variants::VariantResult r = variant->run(chunk[i]);
      results[i].reg1 = chunk[i].cos;
      results[i].norm39 = r.lobe;
      results[i].out = r.out;
    }
    cycles.assign(chunk.size(), 0.0);
    sink(chunk, results, cycles);
  }
}

/// The TLM model: an initiator thread plays the CPU's driver and runs every operation
/// through the `lt` target's registers (N, R, G, B when they change, COS, START, then
/// the outputs and inspection registers), under a 1 µs quantum keeper as a virtual
/// platform would. Cycles are the START write's annotated delay in clock periods.
class TlmInitiator : public sc_core::sc_module {
 public:
  TlmInitiator(sc_core::sc_module_name name, const RunSettings& settings,
               const OperandSource& source, const ResultSink& sink)
      : sc_module(name),
        period_(static_cast<double>(settings.clock_period_ps), sc_core::SC_PS),
        target_("lt_target", settings.config, period_),
        driver_(socket_, 0, keeper_),
        source_(source),
        sink_(sink),
        chunk_size_(settings.chunk_size) {
    SPECULAR_HAS_PROCESS(TlmInitiator);
    socket_.bind(target_.socket);
    target_.done_irq(irq_);
    // The power trace (issue 61): for the CSV and for the target's view in a VCD.
    if (settings.power_window || !settings.vcd_base.empty()) {
      target_.trace_power(sc_core::sc_time(static_cast<double>(settings.power_window_ps), sc_core::SC_PS));
      if (settings.power_window)
        target_.on_power_window([callback = settings.power_window, window_ns = settings.power_window_ps / 1000.0,
                                 pj = 0.0](const sc_core::sc_time& end, double mw) mutable {
          pj += mw * window_ns;  // mW x ns = pJ
          callback(end.to_seconds() * 1e9, mw, pj);
        });
    }
    SC_THREAD(drive);
  }

  /// The target, for its trace and its energy.
  const SpecularLtTarget& target() const { return target_; }

  std::exception_ptr failure;

 private:
  void drive() {
    try {
      tlm::tlm_global_quantum::instance().set(sc_core::sc_time(1, sc_core::SC_US));
      keeper_.reset();
      std::vector<Operands> chunk;
      std::vector<Result> results;
      std::vector<double> cycles;
      chunk.reserve(chunk_size_);
      while (source_(chunk, chunk_size_)) {
        results.resize(chunk.size());
        cycles.resize(chunk.size());
        for (std::size_t i = 0; i < chunk.size(); ++i) {
          results[i] = driver_.compute_inspected(chunk[i]);
          cycles[i] = driver_.operation_duration() / period_;
        }
        sink_(chunk, results, cycles);
      }
      keeper_.sync();
    } catch (...) {
      failure = std::current_exception();
    }
    sc_core::sc_stop();
  }

  sc_core::sc_time period_;
  tlm_utils::simple_initiator_socket<TlmInitiator, 32> socket_{"socket"};
  SpecularLtTarget target_;
  sc_core::sc_signal<bool> irq_{"done_irq"};
  tlm_utils::tlm_quantumkeeper keeper_;
  SpecularDriver driver_;
  const OperandSource& source_;
  const ResultSink& sink_;
  std::size_t chunk_size_;
};

void run_tlm_model(const RunSettings& settings, const OperandSource& source,
                   const ResultSink& sink) {
  sc_core::sc_report_handler::set_handler(kernel_reports_to_stderr);
  TlmInitiator initiator("tb", settings, source, sink);
  sc_core::sc_trace_file* vcd = nullptr;
  if (!settings.vcd_base.empty()) {  // the target's view (waveforms/specular_tlm.gtkw)
    vcd = sc_core::sc_create_vcd_trace_file(settings.vcd_base.c_str());
    vcd->set_time_unit(1, sc_core::SC_PS);
    initiator.target().trace(vcd);
  }
  sc_core::sc_start();
  if (vcd != nullptr) sc_core::sc_close_vcd_trace_file(vcd);
  if (initiator.failure) std::rethrow_exception(initiator.failure);
  if (settings.tlm_energy) settings.tlm_energy(initiator.target().energy());
}

}  // namespace

void run_operations(const RunSettings& settings, const OperandSource& source,
                    const ResultSink& sink) {
  switch (settings.model) {
    case Model::pin: return run_on_pins<PinHarness>(settings, source, sink);
    case Model::rtl:
#ifdef SPECULAR_HAS_RTL_TWIN
      return run_on_pins<RtlHarness>(settings, source, sink);
#else
      throw UsageError("--model rtl: this specular_tb was built without the RTL twin "
                       "(configured with -DSPECULAR_BUILD_RTL=OFF)");
#endif
    case Model::rtl_sync:
#ifdef SPECULAR_HAS_RTL_TWIN
      return run_on_pins<RtlSyncHarness>(settings, source, sink);
#else
      throw UsageError("--model rtl-sync: this specular_tb was built without the RTL twin "
                       "(configured with -DSPECULAR_BUILD_RTL=OFF)");
#endif
    case Model::core: return run_core_model(settings, source, sink);
    case Model::tlm: return run_tlm_model(settings, source, sink);
    case Model::variant: return run_variant_model(settings, source, sink);
  }
}

void run_operations(const RunSettings& settings, const std::vector<Operands>& operations,
                    std::vector<Result>& results, std::vector<double>& cycles) {
  results.clear();
  cycles.clear();
  std::size_t position = 0;
  const OperandSource source = [&](std::vector<Operands>& chunk, std::size_t max) {
    chunk.clear();
    while (chunk.size() < max && position < operations.size()) chunk.push_back(operations[position++]);
    return !chunk.empty();
  };
  const ResultSink sink = [&](const std::vector<Operands>&, const std::vector<Result>& r,
                              const std::vector<double>& c) {
    results.insert(results.end(), r.begin(), r.end());
    cycles.insert(cycles.end(), c.begin(), c.end());
  };
  run_operations(settings, source, sink);
}

}  // namespace tb
}  // namespace specular
