// The verilated model behind an RTL twin's pins (RtlDeviceBase), once for both twins:
// RtlModel<Top, Nets> over the verilated class (Vspecular_device_cc,
// Vspecular_device_sync_cc) and the nets only that twin observes.
#pragma once

// Verilator's headers first: they define vl_time_stamp64() one way with SystemC's
// headers already seen and another without, and the model was compiled without them.
#include <verilated.h>
#include <verilated_fst_c.h>
#include <verilated_vcd_c.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "specular/arith.h"
#include "specular/rom38_banks.h"
#include "specular/twin/rtl_device_base.h"
#include "rom_loader.h"
#include "rtl_coverage.h"
#include "thread_context_guard.h"
#include "verilated_clock.h"

namespace specular {

/// The verilated model (plain C++, evaluated from the twin's one process) and
/// Verilator's waveform writer (VCD, or FST for a model verilated with --trace-fst:
/// one format per verilated class in Verilator 5); the class Verilator made lives in
/// RtlModel.
struct RtlDeviceBase::Verilated {
  /// The channels bound to the input pins (end_of_elaboration).
  struct Inputs {
    const sc_core::sc_signal_in_if<code_t>*pin17, *pin18, *pin19, *pin20, *pin21, *pin22, *pin23;
    const sc_core::sc_signal_in_if<bool>*pin27, *pin28, *pin29, *pin30, *pin31, *pin32, *pin33, *pin34;
  };
  VerilatedContext context;
  std::uint64_t last_eval_ps = 0;  ///< when the model was last evaluated
  bool evaluated = false;
  Inputs inputs{};

  virtual ~Verilated() = default;
  /// Copies the pins into the model, evaluates it and writes the outputs that changed.
  /// `rising_edge_only`: called at rising edges of pin 28 only (a synchronous device
  /// without a trace); the model is first shown the falling edge it has not seen.
  virtual void evaluate(RtlDeviceBase& device, bool rising_edge_only) = 0;
  /// Whether the class has trace code (a specialised verilation has none).
  virtual bool traceable() const = 0;
  /// Verilated with its configuration fixed (FIXED_CONFIG = 1).
  virtual bool fixed() const = 0;
  /// Whether the model writes FST (its class verilated with --trace-fst), else VCD.
  virtual bool fst() const = 0;
  /// Opens Verilator's writer on `path` (1 ps resolution, SystemC's) and lets it trace
  /// every net of the model (traceable() only).
  virtual void open_writer(const std::string& path) = 0;
  /// Whether a writer is open.
  virtual bool writing() const = 0;
  /// The nets' values at `ps` into the open writer.
  virtual void dump(std::uint64_t ps) = 0;
  /// Closes the open writer (if any).
  virtual void close_writer() = 0;
};

/// Whether a verilated class was built with trace code for `Writer` (Verilator's TRACE
/// option for VerilatedVcdC, TRACE_FST for VerilatedFstC).
template <class Top, class Writer, class = void>
struct HasTrace : std::false_type {};
template <class Top, class Writer>
struct HasTrace<Top, Writer, std::void_t<decltype(std::declval<Top&>().trace(
                                 static_cast<Writer*>(nullptr), 0))>> : std::true_type {};

/// `Top`: the class Verilator made (its root header included too: the ROMs are written
/// through top.rootp). `Nets`: the twin's own observed nets, with
/// `using Device = ...;` (the twin) and
/// `template <class Top, class Update> void update(Device&, const Top&, const Update&)`
/// that passes each net's last bits, its bits now and its write to `update`.
/// `Writer`: Verilator's writer the class was verilated for (VerilatedVcdC for --trace,
/// VerilatedFstC for --trace-fst; unused by a class without trace code).
/// `Fixed`: Top was verilated with its configuration as parameters (FIXED_CONFIG = 1,
/// twin/fixed/rtl_sync_fixed.cmake); it reads no pin 19, 20, 34 nor configuration input,
/// so evaluate() checks that the pins carry the values it was built with.
template <class Top, class Nets, class Writer = VerilatedVcdC, bool Fixed = false>
struct RtlModel final : RtlDeviceBase::Verilated {
  /// The model's outputs after the last evaluation, as its port bits.
  struct Outputs {
    std::uint64_t pin24, pin25, pin26, reg9, reg1, rom38, norm, done35, select36;
  };
  ThreadContextGuard context_guard{context};  // before the model: see there
  Top top{&context};
  RtlCoverageScope coverage{context};  // after the model: read before it goes
  std::unique_ptr<Writer> writer;
  Outputs outputs{};
  Nets nets{};
  bool outputs_valid = false;

  /// The policies, tied off for the life of the device (configuration inputs).
  code_t fixed_h19, fixed_a20;  ///< the codes a fixed model was built with (its Config's)

  explicit RtlModel(const Config& config)
      : fixed_h19(pin19_code(config)), fixed_a20(pin20_code(config)) {
    load_rom_words(*top.rootp, Formats(config.widths));
    top.cfg_literal = config.saturation == Saturation::literal;
    top.cfg_rom38_bank = rom38_bank(config);
  }
  ~RtlModel() override {
    writer.reset();  // the writer goes before the model it traces
    context_guard.enter();  // its scopes unregister there (thread_context_guard.h)
  }

  static std::unique_ptr<RtlDeviceBase::Verilated> make(const Config& config) {
    return std::make_unique<RtlModel>(config);
  }

  bool traceable() const override { return HasTrace<Top, Writer>::value; }
  bool fixed() const override { return Fixed; }
  bool fst() const override { return std::is_same_v<Writer, VerilatedFstC>; }
  void open_writer(const std::string& path) override {
    if constexpr (HasTrace<Top, Writer>::value) {
      writer = std::make_unique<Writer>();
      top.trace(writer.get(), 99);
      // SystemC's time resolution (1 ps by default) is the waveform's time unit.
      writer->set_time_resolution("1ps");
      writer->set_time_unit("1ps");
      writer->open(path.c_str());
    } else {
      throw std::logic_error("open_writer('" + path + "'): this verilation has no trace code");
    }
  }
  bool writing() const override { return writer != nullptr; }
  void dump(std::uint64_t ps) override { writer->dump(ps); }
  void close_writer() override {
    if (!writer) return;
    writer->close();
    writer.reset();
  }

  void evaluate(RtlDeviceBase& device, bool rising_edge_only) override {
    // The model runs at the default widths only (constructor): compile-time masks.
    using F = DefaultFormats;
    constexpr auto bits = [](code_t code, const FixedFormat& format) {
      return static_cast<std::uint64_t>(code) & ((std::uint64_t{1} << format.width()) - 1);
    };
    const Inputs& in = inputs;
    if constexpr (Fixed) {
      if (in.pin19->read() != fixed_h19 || in.pin20->read() != fixed_a20 || !in.pin34->read())
        SC_REPORT_ERROR("specular/rtl",
                        "pins 19, 20 or 34 differ from the constants this specialised "
                        "synchronous RTL model was verilated with (docs/rtl.md)");
    }
    if (rising_edge_only && top.pin28_clk && in.pin28->posedge()) {
      // The falling edge since the last rising one, where nothing changes.
      if constexpr (Fixed) {
        show_clock_low(top);  // verilated_clock.h
      } else {
        top.pin28_clk = 0;
        top.eval();
      }
    }
    top.pin17_cos = static_cast<std::uint32_t>(bits(in.pin17->read(), F::cos));
    top.pin18_n = static_cast<std::uint16_t>(bits(in.pin18->read(), F::n));
    top.pin19_h = static_cast<std::uint16_t>(bits(in.pin19->read(), F::mux4));
    top.pin20_a = bits(in.pin20->read(), F::reg9);
    top.pin21_r = static_cast<std::uint8_t>(bits(in.pin21->read(), F::rgb));
    top.pin22_g = static_cast<std::uint8_t>(bits(in.pin22->read(), F::rgb));
    top.pin23_b = static_cast<std::uint8_t>(bits(in.pin23->read(), F::rgb));
    top.pin27_start = in.pin27->read();
    top.pin28_clk = in.pin28->read();
    top.pin29_reset_n = in.pin29->read();
    top.pin30_load_n = in.pin30->read();
    top.pin31_load_r = in.pin31->read();
    top.pin32_load_g = in.pin32->read();
    top.pin33_load_b = in.pin33->read();
    top.pin34_carry = in.pin34->read();
    top.eval();
    // Only outputs whose bits changed go back to their pins (signed buses sign-extended
    // from their width): a write per output and evaluation would cost as much as the
    // evaluation itself (docs/performance.md).
    Outputs& was = outputs;
    const bool all = !outputs_valid;
    outputs_valid = true;
    const auto update = [all](auto& last, auto now, auto write) {
      if (all || now != last) {
        last = now;
        write(now);
      }
    };
    RtlDeviceBase& d = device;
    update(was.pin24, top.pin24_r, [&](std::uint64_t x) { d.pin24_r.write(arith::wrap(F::out, static_cast<code_t>(x))); });
    update(was.pin25, top.pin25_g, [&](std::uint64_t x) { d.pin25_g.write(arith::wrap(F::out, static_cast<code_t>(x))); });
    update(was.pin26, top.pin26_b, [&](std::uint64_t x) { d.pin26_b.write(arith::wrap(F::out, static_cast<code_t>(x))); });
    update(was.reg9, top.obs_reg9_q, [&](std::uint64_t x) { d.reg9_q.write(arith::wrap(F::reg9, static_cast<code_t>(x))); });
    update(was.reg1, top.obs_reg1_q, [&](std::uint64_t x) { d.reg1_q.write(static_cast<code_t>(x)); });
    update(was.rom38, top.obs_rom38_k, [&](std::uint64_t x) { d.rom38_k.write(static_cast<code_t>(x)); });
    update(was.norm, top.obs_mul39_norm, [&](std::uint64_t x) { d.mul39_norm.write(arith::wrap(F::norm, static_cast<code_t>(x))); });
    update(was.done35, top.pin35_done, [&](std::uint64_t x) { d.pin35_done.write(x != 0); });
    update(was.select36, top.obs_select36, [&](std::uint64_t x) { d.select36.write(x != 0); });
    nets.update(static_cast<typename Nets::Device&>(device), top, update);
  }
};

}  // namespace specular
