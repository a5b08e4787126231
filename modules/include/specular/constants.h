/// \file
/// The constants on pins 19 (h) and 20 (a), and the scale s folded into ROM 38, for
/// each `Constants` policy: frozen here, with the values specular_constants found.
///
/// Pins 19 and 20 get their codes from this one place (core, pin harness, TLM target,
/// reference); docs/study.md §5 says how the values were found and why they are optimal.
#pragma once

#include "specular/format.h"

namespace specular {

/// One policy's constants, as the search found them (exact codes, not rounded reals).
struct ConstantValues {
  code_t a_code;        ///< pin 20: a = a_code · 2^−a_frac_bits
  int a_frac_bits;      ///< fraction bits a_code needs
  code_t h_code;        ///< pin 19: h = h_code · 2^−h_frac_bits
  int h_frac_bits;      ///< fraction bits h_code needs
  double max_error;     ///< the search's max_x |s·A − 2^−x| (a test recomputes it)

  /// The constant a on pin 20, as a real (1.0 under Constants::patent).
  double a() const;
  /// The constant h on pin 19, as a real (½ under Constants::patent).
  double h() const;
  /// ROM 38's scale: the peak made exact, s = 1/(a − h·log2 a).
  double s() const;
};

/// The frozen constants of `policy` (modules/src/constants.cpp).
const ConstantValues& constant_values(Constants policy);

/// Pin 19's code in multiplexer 4's format, and pin 20's in register 9's format.
/// Throws std::invalid_argument, naming the width and the smallest that holds the
/// constant, when the bus has fewer fraction bits than the constant needs.
code_t pin19_code(const Formats& formats, Constants policy);
/// Pin 20's code (a) in register 9's format; throws as pin19_code() does.
code_t pin20_code(const Formats& formats, Constants policy);

}  // namespace specular
