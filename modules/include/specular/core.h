/// \file
/// The bit-accurate core: the two passes of Fig. 1 without the SystemC kernel.
///
/// It calls the per-block functions of arith.h in the order the datapath does, so its
/// results are the pin model's to the bit (a test proves it). Use it where cycles do
/// not matter: sweeps, the TLM `lt` model, rendering, studies.
#pragma once

#include <array>

#include "specular/arith.h"
#include "specular/constants.h"
#include "specular/format.h"

namespace specular {

/// Everything fixed when a device is built: widths and the three policies.
struct Config {
  Widths widths{};                                      ///< bus widths (docs/design.md)
  Normalisation normalisation = Normalisation::patent;  ///< what ROM 38 holds
  Saturation saturation = Saturation::clamp;            ///< adder 8 on a negative sum
  Constants constants = Constants::patent;              ///< pins 19 (h), 20 (a), ROM 38's scale
};

/// The codes pins 19 (h) and 20 (a) carry in a device built with `config`: the one
/// place the core, the pin harness, the TLM target and the tests take them from.
inline code_t pin19_code(const Config& config) {
  return pin19_code(Formats(config.widths), config.constants);
}
/// Pin 20's code (the constant a) in register 9's format, for a device built with `config`.
inline code_t pin20_code(const Config& config) {
  return pin20_code(Formats(config.widths), config.constants);
}

/// The operands as the device's registers hold them (codes, already checked).
struct Operands {
  code_t cos = 0;                 ///< register 1 (U1.16 code)
  code_t n = 1;                   ///< register 2
  std::array<code_t, 3> rgb{};    ///< registers 10, 11, 12
};

/// What the device's registers and output pins hold after one operation.
struct Result {
  code_t reg1 = 0;                ///< register 1: the cos code actually used
  code_t reg9_pass1 = 0;          ///< register 9 after pass 1: a − n·log2 cos λ
  code_t reg9_pass2 = 0;          ///< register 9 after pass 2: A ≈ cos^n λ / s
  code_t rom38_k = 0;             ///< ROM 38: s·K(n)
  code_t norm39 = 0;              ///< multiplier 39: s·K(n)·A
  std::array<code_t, 3> out{};    ///< pins 24, 25, 26
};

/// The formats Formats(Widths{}) derives (docs/design.md), as compile-time constants.
/// Core checks at construction that its formats equal these and then runs with them,
/// so shifts, masks and rounding constants are immediates (docs/performance.md: about
/// 2x on the core); other widths run the same functions on the run-time Formats.
struct DefaultFormats {
  static constexpr bool compile_time = true;         ///< members are constants (arith.h)
  static constexpr Widths widths{};                  ///< the default widths
  static constexpr FixedFormat cos{false, 1, 16};    ///< Formats::cos: U1.16
  static constexpr FixedFormat n{false, 10, 0};      ///< Formats::n: U10.0
  static constexpr FixedFormat rgb{false, 8, 0};     ///< Formats::rgb: U8.0
  static constexpr FixedFormat mux4{false, 10, 8};   ///< Formats::mux4: U10.8
  static constexpr FixedFormat log2{true, 5, 22};    ///< Formats::log2: S5.22
  static constexpr FixedFormat reg9{true, 14, 22};   ///< Formats::reg9: S14.22
  static constexpr FixedFormat rom38{false, 9, 16};  ///< Formats::rom38: U9.16
  static constexpr FixedFormat norm{true, 10, 20};   ///< Formats::norm: S10.20
  static constexpr FixedFormat out{true, 18, 13};    ///< Formats::out: S18.13
};

/// True when `formats` are DefaultFormats' (every constant the hot paths read from it):
/// only then may a caller run the arithmetic on DefaultFormats{} instead of `formats`.
bool has_default_formats(const Formats& formats);

/// The device as a plain C++ object: bit-accurate, no clock, no SystemC.
///
/// The datapath of Fig. 1 computed as the netlist computes it, to the bit, without the
/// clock (no SystemC needed; link SpecularUnit::core).
///
/// Build it once per Config (the ROMs are filled in the constructor), then call
/// operands() to check and quantise user values and run() for each operation:
/// \code
/// specular::Core core;                                   // the patent's defaults
/// specular::Result r = core.run(core.operands(0.9, 20, 255, 128, 0));
/// double red = core.formats().out.to_real(r.out[0]);     // pin 24, K·A·R
/// \endcode
class Core {
 public:
  /// Builds ROM 5, ROM 38 and the pin 19/20 constants for `config`. Throws
  /// std::invalid_argument naming the width or constant when `config.widths` is out of
  /// range (Widths::validate) or a table does not fit its format.
  explicit Core(const Config& config = Config{});

  /// One operation: pass 1 (select 36 = 0), pass 2 (select 36 = 1), then the
  /// combinational tail (ROM 38, multiplier 39, multipliers 13–15).
  /// Throws std::out_of_range, naming the operand and its range, for a code outside
  /// its input bus (register 1, 2 or 10–12) — possible only for Operands built by
  /// hand rather than by operands(): the multipliers' fast path relies on it.
  Result run(const Operands& in) const {
    if (!on_input_buses(in)) refuse(in);
    return default_formats_ ? run_with(DefaultFormats{}, in) : run_with(formats_, in);
  }

  /// True when the formats are the defaults and run() takes the constant-folded path.
  bool uses_default_formats() const { return default_formats_; }
  /// run() on the run-time Formats even where the constant path applies: the test
  /// that proves both paths give the same bits calls it (tests/test_bench_core_paths.cpp).
  Result run_generic(const Operands& in) const {
    if (!on_input_buses(in)) refuse(in);
    return run_with(formats_, in);
  }

  /// Operands from user values: checks ranges (throws std::out_of_range naming the
  /// value and its allowed range) and quantises cos λ to register 1's format.
  Operands operands(double cos_lambda, long long n, long long r, long long g, long long b) const;

  /// The configuration the core was built with.
  const Config& config() const { return config_; }
  /// The bus formats derived from config().widths.
  const Formats& formats() const { return formats_; }
  /// ROM 5, the log2 unit's mantissa table.
  const arith::Rom5Table& rom5() const { return rom5_; }
  /// ROM 38, s·K(n) for every n.
  const arith::Rom38Table& rom38() const { return rom38_; }
  /// Pin 19's code: the constant h in multiplexer 4's format (½ = 0x80 by default).
  code_t pin19() const { return pin19_; }
  /// Pin 20's code: the constant a in register 9's format (1.0 = 0x400000 by default).
  code_t pin20() const { return pin20_; }

 private:
  template <class FormatSet>
  Result run_with(const FormatSet& f, const Operands& in) const {
    Result r;
    r.reg1 = in.cos;
    r.reg9_pass1 = pass(f, false, in.cos, 0, in.n);
    r.reg9_pass2 = pass(f, true, in.cos, r.reg9_pass1, in.n);
    r.rom38_k = rom38_.k(in.n);
    r.norm39 = arith::mul39(f, r.reg9_pass2, r.rom38_k);
    for (int ch = 0; ch < 3; ++ch) r.out[ch] = arith::mul_rgb(f, r.norm39, in.rgb[ch]);
    return r;
  }

  /// One pass with this device's saturation and pin 19/20 constants (arith::pass).
  template <class FormatSet>
  code_t pass(const FormatSet& f, bool select36, code_t reg1, code_t reg9, code_t reg2) const {
    return arith::pass(f, rom5_, config_.saturation, pin19_, pin20_, select36, reg1, reg9, reg2);
  }

  /// Every operand within its bus's format. The input buses are unsigned and their
  /// largest codes are all ones, so a code fits when nothing is left above its width
  /// (a negative code has bits up to 63): one test for all five, off the hot path's way.
  bool on_input_buses(const Operands& in) const {
    const auto u = [](code_t code) { return static_cast<std::uint64_t>(code); };
    return ((u(in.cos) >> cos_bits_) | (u(in.n) >> n_bits_) |
            ((u(in.rgb[0]) | u(in.rgb[1]) | u(in.rgb[2])) >> rgb_bits_)) == 0;
  }
  [[noreturn, gnu::cold, gnu::noinline]] void refuse(const Operands& in) const;

  Config config_;
  Formats formats_;
  int cos_bits_, n_bits_, rgb_bits_;  ///< widths of registers 1, 2 and 10–12
  code_t pin19_, pin20_;              ///< the constants h and a (pin19_code, pin20_code)
  arith::Rom5Table rom5_;
  arith::Rom38Table rom38_;
  bool default_formats_;
};

}  // namespace specular
