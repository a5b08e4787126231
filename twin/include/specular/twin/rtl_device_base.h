/// \file
/// What the two RTL twins behind the pin interface share (RtlDevice: the drawn device,
/// RtlSyncDevice: the synchronous variant): the pins, the Config they are verilated for,
/// the one process that evaluates the verilated model, and Verilator's VCD. Each twin
/// adds only its own nets and its verilated class (twin/src/rtl_model.h).
#pragma once

#include <memory>
#include <string>

#include "specular/core.h"
#include "specular/device_pins.h"
#include "specular/systemc.h"

namespace specular {

/// What the two RTL twins behind the pins share: pins 17–35 (DevicePins), as
/// SpecularDevice has them. Inside, the
/// verilated model (Verilator's C++ output) and one SC_METHOD, sensitive to the
/// input pins, that copies the pins into the model, evaluates it and writes the
/// outputs that changed back, sign-extending the signed buses. One process activation per input
/// change: Verilator's own SystemC wrapper, with signals of its port types and
/// adapters in between, took about 4 process activations per clock edge and ran
/// slower than the netlist (docs/performance.md). Policies reach the model as its
/// configuration inputs, tied off here: cfg_literal = Saturation::literal,
/// cfg_rom38_bank = the ROM 38 image of the Config's constants and normalisation
/// (rom38_banks.h, docs/rtl.md); pins 19 and 20 carry the constants h and a.
///
/// The model is verilated at the default widths (docs/design.md); a Config with other
/// widths, or one the core refuses, is refused with std::invalid_argument.
class RtlDeviceBase : public DevicePins {
 public:
  ~RtlDeviceBase() override;

  /// The configuration the twin was built with.
  const Config& config() const { return config_; }
  /// The bus formats: the default widths', the only ones the twins are verilated at.
  const Formats& formats() const { return formats_; }
  /// The code to tie pin 19 to: h in multiplexer 4's format (pin19_code).
  code_t constant_h19() const { return pin19_code(config_); }
  /// The code to tie pin 20 to: a in register 9's format (pin20_code).
  code_t constant_a20() const { return pin20_code(config_); }

  /// The SystemC trace file gets nothing from the twin: its nets are traced by
  /// Verilator into the file open_vcd() names (GTKWave: waveforms/specular_rtl.gtkw,
  /// waveforms/specular_rtl_sync.gtkw for the synchronous variant).
  void trace(sc_core::sc_trace_file*) const override {}
  /// Trace every net of the RTL (pins, Fig. 1's buses, the control unit) to `path`:
  /// called before sc_start, from the start of simulation on; called during the
  /// simulation (after allow_tracing()), from now on, until close_vcd() — a window
  /// (`specular_tb --trace-ops`, `--trace-failures`). std::logic_error otherwise.
  /// A name ending in ".fst" gets GTKWave's FST, written by Verilator (the model
  /// verilated with `--trace-fst`); during the simulation, only in the format
  /// allow_tracing() chose.
  void open_vcd(const std::string& path);
  /// Before sc_start: let open_vcd() be called later, during the simulation (the pins
  /// a trace shows as they change are made to wake the model from the start), in FST
  /// if `fst` (the model verilated with `--trace-fst` is used from the start), else VCD.
  void allow_tracing(bool fst = false);
  /// Writes the last instant and closes the file open_vcd() opened (if any).
  void close_vcd();
  /// Whether the model behind the pins is a verilation specialised to config()
  /// (docs/rtl/sync.md, "Specialised verilation"): without tracing (allow_tracing, open_vcd).
  bool fixed() const;

  // ---- what the harness watches (observation outputs both twins have) ----
  wire select36{"select36"};            ///< control output 36: multiplexer select
  bus_signal reg1_q{"reg1_q"};          ///< register 1's output (U1.16)
  bus_signal reg9_q{"reg9_q"};          ///< register 9's output (S14.22)
  bus_signal rom38_k{"rom38_k"};        ///< ROM 38's word s·K(n) (U9.16)
  bus_signal mul39_norm{"mul39_norm"};  ///< multiplier 39's output (S10.20)

 protected:
  struct Verilated;  // the verilated model, its VCD writer, the pins' channels (rtl_model.h)

  /// What tells a twin apart in the shared code: its names in messages and how to
  /// make its verilated model.
  struct Variant {
    const char* class_name;  ///< "RtlDevice": names open_vcd in its error
    const char* twin_name;   ///< "RTL twin": names the twin in constructor errors
    const char* gtkw;        ///< the GTKWave save file for its VCD
    std::unique_ptr<Verilated> (*make_model)(const Config&);         ///< the fastest for a Config
    std::unique_ptr<Verilated> (*make_traced_model)(const Config&);  ///< one that traces VCD
    std::unique_ptr<Verilated> (*make_fst_model)(const Config&);     ///< --trace-fst (issue 27)
    /// Every input is a level sampled at the rising clock edge and nothing changes at
    /// the falling one (the synchronous variant): without a trace the model is evaluated
    /// at rising edges only.
    bool synchronous = false;
  };

  /// Refuses a Config the model was not verilated for and `real_views` (accepted for
  /// DeviceHarness's sake: the twin's waveform is Verilator's own, codes only), then
  /// makes the model with its policies tied off.
  RtlDeviceBase(sc_core::sc_module_name name, const Config& config, bool real_views,
                const Variant& variant);

 private:
  template <class Top, class Nets, class Writer, bool Fixed>
  friend struct RtlModel;
  friend struct RtlSyncFixedModel;

  void before_end_of_elaboration() override;
  void end_of_elaboration() override;
  void start_of_simulation() override;
  void end_of_simulation() override;
  void evaluate();
  void open_writer(const std::string& path);
  void evaluate_at_rising_edge();  ///< Variant::synchronous without tracing

  Variant variant_;
  const char* class_name_;
  Config config_;
  Formats formats_;
  std::unique_ptr<Verilated> rtl_;
  std::string vcd_path_;
  bool traceable_ = false;  ///< open_vcd() may be called during the simulation
};

}  // namespace specular
