/// \file
/// The synchronous variant of the device (rtl/device/specular_device_sync.v) as plain C++:
/// verilated without SystemC and without trace code, clocked here with its protocol
/// (docs/rtl/sync.md, "The synchronous variant"). The fast cycle model: one clock, so each
/// clock period costs two evaluations and nothing iterates over gated clocks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "specular/core.h"

namespace specular {

/// The synchronous variant as a plain C++ cycle model: clocks the verilated device one
/// half period at a time. Start (27),
/// pin 17 and, when n, R, G, B change, pins 18, 21–23 with their loads 30–33 are levels
/// set a quarter period before the start edge and (start and loads) cleared a quarter
/// period after it. Register 1 and register 9's pass 1 are sampled at the rising edge
/// of select 36 (1 T after start), the results at the rising edge of 35 (2 T after
/// start). Starts come every 2 T while n, R, G, B stay, 3 T when they change.
///
/// Verilated at the default widths (docs/design.md) only: a Config with other widths
/// is refused with std::invalid_argument, as is a device the core refuses.
///
/// Two kinds of verilation: the general model, whose configuration (pins 19, 20, 34,
/// saturation, ROM 38 bank) is a set of inputs, and specialised ones with it fixed as
/// Verilog parameters (docs/rtl/sync.md, "Specialised verilation"; the default device's
/// always, others with the CMake list SPECULAR_RTL_SYNC_FIXED). A Config that matches a
/// specialised build runs on it unless `allow_fixed` is false.
class RtlSyncCycleModel {
 public:
  /// The model for `config` (a specialised verilation if one matches and `allow_fixed`);
  /// throws std::invalid_argument for widths other than the defaults or a Config the
  /// core refuses.
  explicit RtlSyncCycleModel(const Config& config = Config{}, bool allow_fixed = true);
  ~RtlSyncCycleModel();
  RtlSyncCycleModel(const RtlSyncCycleModel&) = delete;
  RtlSyncCycleModel& operator=(const RtlSyncCycleModel&) = delete;

  /// Pin 29 low for one clock period (one rising edge): the sequencer returns to idle.
  void reset();
  /// One operation, started on the next rising clock edge.
  Result run(const Operands& in);
  /// Operations back to back at the minimum interval the protocol allows: 2 T while
  /// n, R, G, B stay, 3 T when they change. `out` is resized to match.
  void run_batch(const std::vector<Operands>& in, std::vector<Result>& out);
  /// The same into caller-owned arrays of `count` (no allocation: the bench's loop).
  void run_batch(const Operands* in, Result* out, std::size_t count);
  /// Clock periods from each start edge to the rising edge of 35, as counted in the
  /// last run_batch with a vector (2 by the variant's timing table).
  const std::vector<double>& cycles() const { return cycles_; }
  /// Clock edges (half periods) simulated since construction.
  std::uint64_t half_periods() const;

  /// The configuration the model was built with.
  const Config& config() const { return config_; }
  /// Whether this model runs a verilation specialised to config() (FIXED_CONFIG = 1).
  bool fixed() const;

  class Engine;  // the verilated model behind it (rtl_sync_cycle_model.cpp)

 private:
  Config config_;
  std::unique_ptr<Engine> engine_;
  std::vector<double> cycles_;
};

/// The configurations a specialised verilation of the synchronous variant was built for
/// (default widths): the default device, and those SPECULAR_RTL_SYNC_FIXED lists.
std::vector<Config> rtl_sync_fixed_configs();

}  // namespace specular
