/// \file
/// The RTL twin as plain C++: rtl/device/specular_device.v verilated without SystemC and
/// clocked here edge by edge, with the protocol of DeviceHarness (spec §3). No kernel,
/// no sc_signals: the fast cycle-accurate model (docs/rtl.md, docs/performance.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "specular/core.h"

namespace specular {

/// The RTL twin as a plain C++ cycle model: clocks the verilated device one half period
/// at a time. A start rises with a
/// rising clock edge; cos λ is presented with it, and n, R, G, B (strobes 30–33) a
/// quarter period before it when they change. Results are sampled at the rising edge
/// of 35, register 1 and register 9's pass-1 value at the rising edge of select 36,
/// as DeviceHarness samples them.
///
/// Verilated twice: at the default widths (docs/design.md) and at one other width set
/// (rtl_alternate_widths()), to check that the RTL's parameters follow Formats; a Config
/// with any other widths is refused with std::invalid_argument.
class RtlCycleModel {
 public:
  /// A Config with a specialised verilation (docs/rtl/sync.md, "Specialised verilation")
  /// runs on it unless `allow_fixed` is false.
  explicit RtlCycleModel(const Config& config = Config{}, bool allow_fixed = true);
  ~RtlCycleModel();
  RtlCycleModel(const RtlCycleModel&) = delete;
  RtlCycleModel& operator=(const RtlCycleModel&) = delete;

  /// Pin 29 low for one clock period: the control unit returns to idle.
  void reset();
  /// One operation, started on the next rising clock edge.
  Result run(const Operands& in);
  /// Operations back to back at the minimum interval the protocol allows: 2 T while
  /// n, R, G, B stay, 3 T when they change. `out` is resized to match.
  void run_batch(const std::vector<Operands>& in, std::vector<Result>& out);
  /// Clock periods from each start to the rising edge of 35, as counted in the last
  /// run or run_batch (2.5 by the spec's timing table).
  const std::vector<double>& cycles() const { return cycles_; }
  /// Half clock periods simulated since construction.
  std::uint64_t half_periods() const;

  /// The configuration the model was built with.
  const Config& config() const { return config_; }
  /// Whether this model runs a verilation specialised to config() (FIXED_CONFIG = 1).
  bool fixed() const;

  class Engine;  // the verilated model behind it (rtl_cycle_model.cpp)

 private:
  Config config_;
  std::unique_ptr<Engine> engine_;
  std::vector<double> cycles_;
};

/// The second width set the RTL is verilated at: ROM 5's word 20 bits and register 9
/// S14.16 (docs/rtl.md).
Widths rtl_alternate_widths();

}  // namespace specular
