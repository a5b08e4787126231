/// \file
/// The energy a device has spent so far, by kind: operations (operation_energy.h),
/// register reads and writes, and the clocks in between (calibration.h's BusTable).
/// Kernel-free: the TLM targets keep one (SpecularTarget::energy()), and so can any
/// C++ caller of the core.
#pragma once

#include <cstdint>
#include <memory>

#include "specular/energy/operation_energy.h"

namespace specular {
class Core;
}

namespace specular::energy {

/// The energy so far, in pJ, and what it was spent on.
struct EnergyTally {
  std::uint64_t operations = 0;  ///< results computed
  std::uint64_t reads = 0;       ///< 32-bit register reads (bus beats)
  std::uint64_t writes = 0;      ///< 32-bit register writes (bus beats)
  double clocks = 0;             ///< clock periods elapsed
  double operation_pj = 0;       ///< the operations (operation_energy.h)
  double read_pj = 0;            ///< the reads, beyond the clocks they span
  double write_pj = 0;           ///< the writes, beyond the clocks they span
  double clock_pj = 0;           ///< every clock period elapsed, at the idle clock's figure
  /// Everything: operations, reads, writes and clocks.
  double total_pj() const { return operation_pj + read_pj + write_pj + clock_pj; }
};

/// Counts a device's work and weighs it. The operations' energy is linear in their
/// features, so the meter only sums the features per operation and weighs the sums
/// when asked: an operation costs a few additions on top of computing its features.
class EnergyMeter {
 public:
  /// A meter charging `calibration`'s figures for a device whose buses have `formats`.
  EnergyMeter(Calibration calibration, const Formats& formats);
  ~EnergyMeter();
  /// Moves the counts (and the meter's own Core, if it made one).
  EnergyMeter(EnergyMeter&&) noexcept;
  /// Moves the counts (and the meter's own Core, if it made one).
  EnergyMeter& operator=(EnergyMeter&&) noexcept;

  /// One operation whose registers end at `in` and `r` (Core::run's result for `in`).
  void operation(const Operands& in, const Result& r) {
    const Features x = features_.next(in, r);
    for (std::size_t i = 0; i < feature_count; ++i) sums_[i] += x[i];
    ++operations_;
  }
  /// One operation on `in`, its result computed by the meter's own Core (built at the
  /// first call with `config`): for targets whose results come from elsewhere.
  void operation(const Config& config, const Operands& in);
  /// `words` 32-bit register reads.
  void reads(std::uint64_t words) { reads_ += words; }
  /// `words` 32-bit register writes.
  void writes(std::uint64_t words) { writes_ += words; }
  /// The device was reset: its registers hold reset_state() again.
  void reset_registers() { features_.restart_from(reset_state()); }

  /// The energy so far, with `clocks` clock periods elapsed.
  EnergyTally tally(double clocks) const;
  /// The figures it charges.
  Calibration calibration() const { return calibration_; }

 private:
  Calibration calibration_;
  FeatureStream features_;  ///< the registers the next operation counts from
  Features sums_{};
  std::uint64_t operations_ = 0, reads_ = 0, writes_ = 0;
  std::unique_ptr<Core> core_;  ///< for operation(config, in) only
};

}  // namespace specular::energy
