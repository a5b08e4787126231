/// \file
/// What the transaction level knows of one operation that moves gate-level energy.
///
/// CMOS spends its dynamic energy on toggles, and the toggles of an operation follow
/// from how far its register and bus values lie from the previous operation's: the
/// Hamming distances below. They are the features the energy model is fitted on
/// (scripts/flows/energy/model/fit.py) and evaluated with (operation_energy.h): written once,
/// here, so the fit and the model cannot compute them differently.
#pragma once

#include <array>
#include <cstddef>

#include "specular/core.h"

namespace specular::energy {

/// The device's registers and buses after an operation: its operands and what the
/// core computed from them (Core::run).
struct RegisterState {
  Operands in{};  ///< registers 1, 2, 10–12
  Result r{};     ///< register 9 (both passes), ROM 38, multiplier 39, pins 24–26
};

/// The registers after reset: every code 0 (spec, control unit: reset clears them).
inline RegisterState reset_state() {
  RegisterState s;
  s.in.n = 0;
  return s;
}

/// How many features operation_features() gives.
constexpr std::size_t feature_count = 24;
/// One value per feature, in the order of feature_names.
using Features = std::array<double, feature_count>;
/// The features' names, as fit.py's report and the calibration table name them.
extern const std::array<const char*, feature_count> feature_names;

/// The features of the operation that takes the registers from `before` to `after`,
/// on the buses of `formats` (codes are masked to each bus's width).
Features operation_features(const Formats& formats, const RegisterState& before,
                            const RegisterState& after);

}  // namespace specular::energy
