/// \file
/// The energy of one operation, from what the transaction level knows: the features of
/// operation_features.h weighed by a gate-level fit (calibration.h, docs/energy.md).
#pragma once

#include "specular/energy/calibration.h"
#include "specular/energy/operation_features.h"

namespace specular::energy {

/// Which gate-level device's figures an energy model charges.
enum class Calibration {
  synchronous_device,  ///< specular_device_sync, the IP's datapath: lt, at, axi, the core
  drawn_device,        ///< specular_device, Fig. 2 as drawn: the pin-level and rtl models
};

/// The table of `calibration`.
const CalibrationTable& table(Calibration calibration);
/// A name for reports: "synchronous device (specular_device_sync)" or
/// "drawn device (specular_device)".
const char* calibration_name(Calibration calibration);

/// The energy of a device's operations in turn. It remembers the registers the previous
/// operation left (reset_state() at first), since the toggles from them are what an
/// operation costs.
class OperationEnergy {
 public:
  /// For a device whose buses have `formats` (the fit is for the default widths: other
  /// widths are charged by the same coefficients on their own toggles).
  OperationEnergy(Calibration calibration, const Formats& formats)
      : table_(&table(calibration)), features_(formats), calibration_(calibration) {}

  /// pJ of the operation that leaves the registers at `in` and `r` (Core::run's result
  /// for `in`); the next call counts from them.
  double next(const Operands& in, const Result& r) {
    const Features x = features_.next(in, r);
    double pj = 0;
    for (std::size_t i = 0; i < feature_count; ++i) pj += table_->pj_per_feature[i] * x[i];
    return pj;
  }
  /// The registers back to their reset values (the device was reset).
  void reset() { features_.restart_from(reset_state()); }
  /// The calibration it charges.
  Calibration calibration() const { return calibration_; }

 private:
  const CalibrationTable* table_;
  FeatureStream features_;  ///< the registers the next operation counts from
  Calibration calibration_;
};

}  // namespace specular::energy
