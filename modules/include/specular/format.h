/// \file
/// Every bus's fixed-point format and every ROM's organisation, in one place.
///
/// Values travel through the model as integer codes (`code_t`); a FixedFormat says
/// how a code maps to a real number. Real numbers appear only at the edges (reports,
/// traces, the reference). See docs/design.md for the table of formats and why.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace specular {

/// An integer code on a bus. 64 bits hold every default format with room to spare.
using code_t = std::int64_t;

/// Two's-complement (or unsigned) fixed-point format: [sign] int_bits . frac_bits.
struct FixedFormat {
  bool is_signed = false;  ///< two's complement (S) or unsigned (U)
  int int_bits = 0;   ///< integer bits, not counting the sign bit
  int frac_bits = 0;  ///< fraction bits

  /// Bits on the bus: sign + int_bits + frac_bits.
  constexpr int width() const { return (is_signed ? 1 : 0) + int_bits + frac_bits; }
  /// Largest code: 2^(int_bits + frac_bits) − 1.
  constexpr code_t max_code() const { return (code_t{1} << (int_bits + frac_bits)) - 1; }
  /// Smallest code: −2^(int_bits + frac_bits) if signed, else 0.
  constexpr code_t min_code() const {
    return is_signed ? -(code_t{1} << (int_bits + frac_bits)) : 0;
  }
  /// The code of 1.0: 2^frac_bits.
  constexpr code_t one() const { return code_t{1} << frac_bits; }
  /// The real number a code stands for: code · 2^−frac_bits.
  double to_real(code_t code) const { return std::ldexp(static_cast<double>(code), -frac_bits); }
  /// Resolution: the value of one least significant bit.
  double lsb() const { return std::ldexp(1.0, -frac_bits); }
  /// "S14.24" / "U1.16": how the design note and the reports write a format.
  std::string name() const;
};

/// Normalisation policy: what ROM 38 holds (spec, Decision "normalisation").
enum class Normalisation {
  patent,  ///< K(n) = 2π/(n+2), as claimed (default)
  energy,  ///< K(n) = (n+2)/(2π), makes the exact lobe's hemisphere integral 1
  none,    ///< K(n) = 1, the prototype device UA 22802
  device_energy,  ///< K(n) = 1/I(n), I(n) the equation-6 integral of the device's own
                  ///< clamped register-9 lobe: what multiplier 39 gives integrates to 1
};

/// Constants on pins 20 (a) and 19 (h) and ROM 38's scale s (spec, Decision
/// "constants"): the device computes s·K(n)·max(0, a − h·log2(a − n·log2 cos λ)).
/// The values are frozen in modules/src/constants.cpp (specular_constants found them).
enum class Constants {
  patent,        ///< a = 1, h = ½, s = 1, as the patent says (default)
  minimax_half,  ///< h = ½ kept; a and s minimise the largest error (0.0734)
  minimax,       ///< h on pin 19's 8 fraction bits too (0.0398)
};

/// What adder 8 does with a negative result (spec, Decision "negative results").
enum class Saturation {
  clamp,    ///< saturate at 0 (default; negative light is meaningless)
  literal,  ///< keep the signed value, for study
};

/// The policy's name as the tools' options take it: "patent", "energy", "none", "device-energy".
const char* to_string(Normalisation policy);
/// The policy's name: "clamp" or "literal".
const char* to_string(Saturation policy);
/// The policy's name: "patent", "minimax-half" or "minimax".
const char* to_string(Constants policy);
/// Parse a policy name; throws std::invalid_argument naming the value and the choices.
Normalisation parse_normalisation(const std::string& text);
/// Parse "clamp" or "literal"; throws std::invalid_argument naming the value and the choices.
Saturation parse_saturation(const std::string& text);
/// Parse "patent", "minimax-half" or "minimax"; throws std::invalid_argument naming the
/// value and the choices.
Constants parse_constants(const std::string& text);

/// The widths the designer chooses. Every bus format below is derived from these,
/// so a width changes here and nowhere else. Defaults are justified in docs/design.md.
struct Widths {
  int cos_frac_bits = 16;   ///< pin 17 / register 1: cos λ as U1.F
  int n_bits = 10;          ///< pin 18 / register 2: n as an unsigned integer (1..1000)
  int rgb_bits = 8;         ///< pins 21–23 / registers 10–12: unsigned intensities
  int pin19_frac_bits = 8;  ///< pin 19 / multiplexer 4's bus: h as U10.F (minimax's h = 41/256)
  int rom5_addr_bits = 15;  ///< ROM 5 address: mantissa bits after the leading one
  int rom5_word_bits = 22;  ///< ROM 5 word: fraction bits of log2(1.m) ∈ [0, 1)
  int reg9_int_bits = 14;   ///< adder 8 / register 9 / multiplexer 3 bus: integer bits
  int reg9_frac_bits = 22;  ///< ... and fraction bits (signed format)
  int rom38_int_bits = 9;   ///< ROM 38 word: s·K(n) as U9.F (energy × minimax reaches 272)
  int rom38_frac_bits = 16; ///< ... and its fraction bits
  int norm_int_bits = 10;   ///< multiplier 39 output: K·A as a signed format
  int norm_frac_bits = 20;  ///< ... and its fraction bits
  int out_int_bits = 18;    ///< pins 24–26: K·A·I as a signed format (32 bits in all)
  int out_frac_bits = 13;   ///< ... and its fraction bits

  /// Throws std::invalid_argument naming the offending width and its allowed range.
  void validate() const;
};

/// Sets the width `name` (a member's name above: "cos_frac_bits", "rom5_word_bits", …)
/// to `value`, as the tools' `--width NAME=VALUE` options do; throws
/// std::invalid_argument naming every known name when `name` is none of them. The
/// range is validate()'s concern, once every width is set.
void set_width(Widths& widths, const std::string& name, int value);
/// The names set_width accepts, comma-separated.
std::string width_names();
/// Every width of Widths with the name set_width() takes, in the order of Widths.
struct WidthField {
  const char* name;     ///< the member's name, e.g. "cos_frac_bits"
  int Widths::*member;  ///< the member itself
};
/// Every member of Widths, with its name, in declaration order.
const std::vector<WidthField>& width_fields();

/// Bus formats derived from Widths; computed once, read everywhere.
struct Formats {
  /// Derives every format from `widths`; throws std::invalid_argument as
  /// Widths::validate() does.
  explicit Formats(const Widths& widths = Widths{});
  /// Run-time values (Core's DefaultFormats are the compile-time set: arith.h).
  static constexpr bool compile_time = false;

  Widths widths;       ///< the widths the formats come from
  FixedFormat cos;     ///< pin 17, register 1 (U1.16)
  FixedFormat n;       ///< pin 18, register 2, ROM 38 address (U10.0)
  FixedFormat rgb;     ///< pins 21–23, registers 10–12 (U8.0)
  FixedFormat mux4;    ///< multiplexer 4 output: n or pin 19's h on one bus (U10.8)
  FixedFormat log2;    ///< ROM 5 output: log2 of its input (S5.22)
  FixedFormat reg9;    ///< multiplier 6 / inverter 7 / adder 8 / register 9 / multiplexer 3 (S14.22)
  FixedFormat rom38;   ///< ROM 38 word s·K(n) (U9.16)
  FixedFormat norm;    ///< multiplier 39 output K·A (S10.20)
  FixedFormat out;     ///< pins 24–26, multipliers 13–15 (S18.13)

  /// ROM 5's words: 2^rom5_addr_bits (32 768 by default).
  int rom5_words() const { return 1 << widths.rom5_addr_bits; }
  /// ROM 38's words: one per n code, 2^n_bits (1 024 by default).
  int rom38_words() const { return 1 << widths.n_bits; }
  /// ROM 5's size in bits.
  long rom5_bits() const { return static_cast<long>(rom5_words()) * widths.rom5_word_bits; }
  /// ROM 38's size in bits.
  long rom38_bits() const { return static_cast<long>(rom38_words()) * rom38.width(); }
};

/// Smallest and largest n the device accepts (spec §1).
constexpr unsigned n_min = 1;
constexpr unsigned n_max = 1000;  ///< largest n the device accepts

/// cos λ (a real in [0, 1]) to the code held in register 1, rounded to nearest.
/// Throws std::out_of_range naming the value and the range (NaN included).
code_t quantise_cos(const Formats& formats, double cos_lambda);
/// Checks n ∈ [1, 1000]; throws std::out_of_range naming the value and the range.
unsigned check_n(long long n);
/// Checks an intensity fits the RGB format; throws std::out_of_range naming it.
unsigned check_rgb(const Formats& formats, long long intensity, const char* channel);
/// Checks a cos code is in [0, 1.0]; throws std::out_of_range naming it.
code_t check_cos_code(const Formats& formats, code_t code);

}  // namespace specular
