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
/// on the buses of `formats` (codes are masked to each bus's width). For a stream of
/// operations FeatureStream gives the same values in about 0.6 of the time.
Features operation_features(const Formats& formats, const RegisterState& before,
                            const RegisterState& after);

/// The features of a device's operations in turn, each derived value computed once.
///
/// An operation's last step (pass 2 written, select 36 falling) is also the next
/// operation's "previous" step, and what an operation's own registers give (ROM 5's
/// reads, multiplier 6's and 39's products) is what the next one toggles from: a stream
/// keeps them, so each operation derives them once. With the default widths it runs on
/// DefaultFormats' constants, as Core does (same values: operation_features() is a stream
/// of one step, and test EnergyFeatureStream.KeepsThePreviousOperationsValuesExactly
/// compares the two).
class FeatureStream {
 public:
  /// A stream starting from reset_state(), for a device whose buses have `formats`.
  explicit FeatureStream(const Formats& formats);

  /// The features of the operation that leaves the registers at `in` and `r` (Core::run's
  /// result for `in`), counted from the previous call's registers.
  Features next(const Operands& in, const Result& r);
  /// The registers the next operation counts from: `registers` (reset_state() after a reset).
  void restart_from(const RegisterState& registers);

  /// What one operation's registers give, kept for the next operation: ROM 5's reads and
  /// multiplier 6's products on register 1 (Fig. 2 between operations) and on register
  /// 9's passes, multiplier 39 on pass 1, and the counts of its last step (pass 2
  /// written, select 36 falling), which the next operation counts again as its
  /// "previous" step. Counts are integers, activities in eighths (operation_features.cpp).
  struct Settled {
    RegisterState regs;  ///< the operation's registers
    code_t log_cos = 0;      ///< ROM 5 on register 1's cos
    code_t rom5_cos = 0;     ///< ROM 5's address for it
    code_t n_operand = 0;    ///< multiplexer 4 on register 2 (n)
    code_t log_pass1 = 0;    ///< ROM 5 on register 9's pass 1
    code_t mul6_pass1 = 0;   ///< multiplier 6: that times h
    code_t mul39_pass1 = 0;  ///< multiplier 39: pass 1 times K
    code_t log_pass2 = 0;    ///< ROM 5 on register 9's pass 2
    code_t rom5_pass2 = 0;   ///< ROM 5's address for it
    code_t mul6_pass2 = 0;   ///< multiplier 6: that times h
    int end_rom5_read = 0;          ///< pass 2 written: ROM 5 reads a new word (1) or not
    int end_log2 = 0;               ///< the log2 unit's toggles
    int end_mul6 = 0;               ///< multiplier 6's toggles (on h)
    int end_mul39_activity8 = 0;    ///< multiplier 39's activity, in eighths
    int end_mul_rgb_activity8 = 0;  ///< multipliers 13-15's, in eighths
    int return_rom5_read = 0;       ///< select 36 falls: ROM 5 back on register 1 reads anew
    int return_mul6_activity8 = 0;  ///< multiplier 6's operands back to (cos, n), in eighths
  };

 private:
  Formats formats_;
  bool default_formats_;
  code_t pin19_h_;
  const arith::Rom5Table* rom5_;  ///< shared by every stream of the same widths
  /// The previous operation's and the one being computed, in turn (no copy per operation).
  std::array<Settled, 2> settled_{};
  int last_ = 0;  ///< which of settled_ is the previous operation's
};

}  // namespace specular::energy
