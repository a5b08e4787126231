/// \file
/// The arithmetic of every block of Fig. 1, written once, on integer codes.
///
/// Each function is what one block does between its input and output pins. The
/// block's SC_MODULE calls it from its process; the kernel-free Core calls the same
/// functions in the same order. Nothing here knows about SystemC.
#pragma once

#include <cstdint>
#include <vector>

#include "specular/format.h"

namespace specular {

struct Config;  // core.h: ROM 38's contents depend on the whole configuration

/// The per-block arithmetic of Fig. 1 on integer codes (see arith.h).
namespace arith {

/// The products' width: 64 × 64 bits before rounding. GCC's and Clang's 128-bit integer,
/// marked __extension__ so that a consumer's -Wpedantic stays quiet on this header.
__extension__ typedef __int128 wide_t;

// The block functions take their formats as `const FormatSet&`: the run-time Formats
// (SC_MODULEs, Core with any widths) or Core's DefaultFormats, whose members are
// compile-time constants (`FormatSet::compile_time`), so that every shift and mask
// folds into an immediate on the core's hot path and the multipliers skip overflow
// checks their widths make impossible (docs/performance.md). Same bits either way.

/// Wrap a code to `format`'s width, as a bus of that width would (two's complement).
/// Two shifts: the bits above the width leave at the top, and shifting back
/// sign-extends a signed bus (the same value as mask-and-extend, fewer instructions).
inline code_t wrap(const FixedFormat& format, code_t code) {
  const int unused = 64 - format.width();
  const std::uint64_t bits = static_cast<std::uint64_t>(code) << unused;
  return format.is_signed ? static_cast<code_t>(bits) >> unused
                          : static_cast<code_t>(bits >> unused);
}

/// Saturate a code to `format`'s range (downstream of register 9: silent, by design).
inline code_t saturate(const FixedFormat& format, wide_t value) {
  if (value > format.max_code()) return format.max_code();
  if (value < format.min_code()) return format.min_code();
  return static_cast<code_t>(value);
}

/// Drop `shift` fraction bits, rounding half up (a multiplier's rounding stage).
inline wide_t round_shift(wide_t value, int shift) {
  if (shift <= 0) return value * (wide_t{1} << -shift);  // a multiply: defined for value < 0
  return (value + (wide_t{1} << (shift - 1))) >> shift;
}

/// The 128-bit tails of the multipliers, out of line: never taken at the default
/// widths, they would only crowd the core's hot loop (docs/performance.md).
[[gnu::cold, gnu::noinline]] inline code_t wide_multiply_round_saturate(const FixedFormat& format,
                                                                       code_t a, code_t b, int shift) {
  return saturate(format, round_shift(static_cast<wide_t>(a) * b, shift));
}
/// The same, wrapped to `format` instead of saturated (multiplier 6's 128-bit tail).
[[gnu::cold, gnu::noinline]] inline code_t wide_multiply_round_wrap(const FixedFormat& format,
                                                                   code_t a, code_t b, int shift) {
  return wrap(format, static_cast<code_t>(round_shift(static_cast<wide_t>(a) * b, shift)));
}

/// A rounded value saturated to `format`: in range when only sign bits sit above the
/// format's magnitude bits, otherwise its minimum or maximum code.
inline code_t saturate_rounded(const FixedFormat& format, code_t value) {
  const code_t above = value >> (format.int_bits + format.frac_bits);
  if (above == 0 || (format.is_signed && above == -1)) return value;
  return value < 0 ? format.min_code() : format.max_code();
}

/// a × b with `shift` fraction bits dropped (rounding half up), saturated to `format`:
/// the tail of multipliers 39 and 13–15. On 64 bits when neither the product nor the
/// rounding overflows (always, at the default widths: docs/performance.md), otherwise
/// on 128 bits; the result is the same either way.
inline code_t multiply_round_saturate(const FixedFormat& format, code_t a, code_t b, int shift) {
  code_t product, biased;
  if (shift > 0 && !__builtin_mul_overflow(a, b, &product) &&
      !__builtin_add_overflow(product, code_t{1} << (shift - 1), &biased))
    return saturate_rounded(format, biased >> shift);
  return wide_multiply_round_saturate(format, a, b, shift);
}

/// The same without overflow checks, for the compile-time formats of Core's hot path:
/// only where both operands are within formats at most 62 bits wide together, so that
/// product and rounding bias stay below 2^63 (callers static_assert the widths).
template <int shift>
inline code_t multiply_round_saturate_in_range(const FixedFormat& format, code_t a, code_t b) {
  static_assert(shift > 0, "a multiplier drops fraction bits");
  return saturate_rounded(format, (a * b + (code_t{1} << (shift - 1))) >> shift);
}

// ---- Multiplexer 3: ROM 5 address bus -------------------------------------------
/// in0 = register 1 (cos λ, U1.16) aligned to register 9's format, in1 = register 9.
template <class FormatSet>
inline code_t mux3(const FormatSet& f, bool select36, code_t reg1, code_t reg9) {
  return select36 ? reg9 : reg1 << (f.reg9.frac_bits - f.cos.frac_bits);
}

// ---- Leading-one normaliser (rtl/primitives/leading_one_normaliser.v) ------------------------
/// What a leading-one detector and its shifter give: the index of the highest one of a
/// `width`-bit code x > 0 and x shifted left until that one sits at bit width − 1. ROM 5
/// addresses its mantissa table with it; the design variants normalise a divisor with it.
struct LeadingOne {
  int msb = 0;                  ///< index of the highest one
  std::uint64_t normalised = 0; ///< x << (width − 1 − msb)
};
/// The leading one of `x` (> 0) within `width` bits (≤ 64): see LeadingOne.
inline LeadingOne leading_one(std::uint64_t x, int width) {
  const int msb = 63 - __builtin_clzll(x);
  return LeadingOne{msb, x << (width - 1 - msb)};
}

// ---- ROM 5: log2 unit (leading-one detector + mantissa ROM) ---------------------
/// ROM 5 is the usual hardware log2 unit (spec §4): a leading-one detector finds the
/// exponent, the next `rom5_addr_bits` bits address a table of log2(1.m), and the
/// exponent is added back. Non-positive inputs (a zero cos code, or the value that
/// register 9 holds after a saturated or literal second pass) read as log2 of the
/// smallest cos code, −F (spec, Decision "log2 0").
class Rom5Table {
 public:
  /// Fills the table for `formats` (2^rom5_addr_bits words of rom5_word_bits bits).
  explicit Rom5Table(const Formats& formats);
  /// log2 of a multiplexer-3 code, in ROM 5's output format.
  code_t log2(code_t bus) const {
    return lookup(words_.data(), addr_bits_, word_bits_, bus_frac_bits_, zero_log2_, bus);
  }
  /// The same, with the organisation read from a FormatSet (constants for the core's
  /// DefaultFormats). Only valid for the formats this table was built from.
  template <class FormatSet>
  code_t log2(const FormatSet& f, code_t bus) const {
    return lookup(words_.data(), f.widths.rom5_addr_bits, f.log2.frac_bits, f.reg9.frac_bits,
                  -(static_cast<code_t>(f.cos.frac_bits) << f.log2.frac_bits), bus);
  }
  /// The leading-one detector and the mantissa ROM: written once for both log2()s.
  static code_t lookup(const std::uint32_t* words, int addr_bits, int word_bits,
                       int bus_frac_bits, code_t zero_log2, code_t bus) {
    if (bus <= 0) return zero_log2;
    // The leading one moves to bit 63 and out; the next addr_bits bits are the address
    // (zero-filled when fewer bits follow the leading one).
    const LeadingOne one = leading_one(static_cast<std::uint64_t>(bus), 64);
    const code_t exponent = one.msb - bus_frac_bits;
    return exponent * (code_t{1} << word_bits) + words[mantissa_address(one, addr_bits)];
  }
  /// The mantissa table's address for a bus code > 0 whose leading one is `one` (found
  /// within 64 bits): the `addr_bits` bits after it. The energy model's ROM 5 reads
  /// (operation_features.cpp) address the table the same way.
  static std::uint64_t mantissa_address(const LeadingOne& one, int addr_bits) {
    return (one.normalised << 1) >> (64 - addr_bits);
  }
  /// The table itself, for reports and tests: word a = round(log2(1 + a/2^M) · 2^W).
  const std::vector<std::uint32_t>& words() const { return words_; }

 private:
  std::vector<std::uint32_t> words_;
  int addr_bits_;
  int word_bits_;
  int bus_frac_bits_;
  code_t zero_log2_;
};

// ---- Multiplexer 4: multiplier 6's second operand ------------------------------
/// in0 = register 2 (n), in1 = pin 19 (the constant h: ½ under the patent's
/// constants); both on the U10.F bus.
template <class FormatSet>
inline code_t mux4(const FormatSet& f, bool select36, code_t reg2, code_t pin19_h) {
  return select36 ? pin19_h : reg2 << f.mux4.frac_bits;
}

// ---- Multiplier 6 -------------------------------------------------------------
/// log2 × (n or h), rounded to nearest to adder 8's format and wrapped to its width.
template <class FormatSet>
inline code_t mul6(const FormatSet& f, code_t rom5_log2, code_t mux4_operand) {
  if constexpr (FormatSet::compile_time) {
    // A wrapping multiplier keeps bits shift .. shift + width − 1 of product + bias, and
    // those are the same in the product modulo 2^64 as in the exact one: no overflow
    // check, for any operands (unsigned arithmetic: wrapping is defined).
    constexpr int shift = FormatSet::log2.frac_bits + FormatSet::mux4.frac_bits - FormatSet::reg9.frac_bits;
    static_assert(shift > 0 && shift + FormatSet::reg9.width() <= 64, "kept bits within 64");
    const std::uint64_t product = static_cast<std::uint64_t>(rom5_log2) * static_cast<std::uint64_t>(mux4_operand);
    return wrap(f.reg9, static_cast<code_t>((product + (std::uint64_t{1} << (shift - 1))) >> shift));
  } else {
    const int shift = f.log2.frac_bits + f.mux4.frac_bits - f.reg9.frac_bits;
    code_t product, biased;
    if (shift > 0 && !__builtin_mul_overflow(rom5_log2, mux4_operand, &product) &&
        !__builtin_add_overflow(product, code_t{1} << (shift - 1), &biased))
      return wrap(f.reg9, biased >> shift);  // 64 bits suffice (the default widths)
    return wide_multiply_round_wrap(f.reg9, rom5_log2, mux4_operand, shift);
  }
}

// ---- Inverter block 7 ----------------------------------------------------------
/// Bitwise NOT across the bus (with carry-in 34 this makes adder 8 subtract).
template <class FormatSet>
inline code_t inv7(const FormatSet& f, code_t product) { return wrap(f.reg9, ~product); }

// ---- Combinational adder 8 -----------------------------------------------------
/// pin 20 (a: 1.0 under the patent's constants) + inverted product + carry-in 34
/// = a − product, modulo the bus width.
/// Under Saturation::clamp a negative sum saturates at 0 (spec, Decision).
template <class FormatSet>
inline code_t adder8(const FormatSet& f, Saturation saturation, code_t pin20_a, code_t inverted,
                     bool carry34) {
  const code_t sum = wrap(f.reg9, pin20_a + inverted + (carry34 ? 1 : 0));
  return (saturation == Saturation::clamp && sum < 0) ? 0 : sum;
}

// ---- The two passes ----------------------------------------------------------------
/// The combinational path from registers 1, 2, 9 to adder 8's output for a given
/// select 36: multiplexers 3, 4 → ROM 5 → multiplier 6 → inverter 7 → adder 8.
template <class FormatSet>
inline code_t pass(const FormatSet& f, const Rom5Table& rom5, Saturation saturation, code_t pin19_h,
                   code_t pin20_a, bool select36, code_t reg1, code_t reg9, code_t reg2) {
  const code_t address = mux3(f, select36, reg1, reg9);
  const code_t operand = mux4(f, select36, reg2, pin19_h);
  const code_t product = mul6(f, rom5.log2(f, address), operand);
  return adder8(f, saturation, pin20_a, inv7(f, product), true);
}

/// I(n) = 2π ∫₀¹ A(t)·t dt of the device's own clamped register-9 lobe, integrated
/// exactly over each cos code's rounding interval (the lobe is constant on each):
/// the equation-6 integral normalisation `device_energy` divides by.
double register9_lobe_integral(const Formats& formats, const Rom5Table& rom5, code_t pin19_h,
                               code_t pin20_a, code_t n);

// ---- ROM 38: normalisation coefficient K(n) ------------------------------------
/// ROM 38's table: s·K(n) for every address 0 to 2^n_bits − 1 (n = 0 and n > 1000
/// included: the same formula), rounded to the ROM word (spec §1). Under `device_energy` the word is
/// 1/I(n) (s folds into it). Throws std::invalid_argument naming n and the format if a
/// word does not fit: ROM 38 is widened, never left to saturate.
class Rom38Table {
 public:
  /// Fills the table for `config`'s normalisation and constants; throws
  /// std::invalid_argument naming n and the format if a word does not fit.
  Rom38Table(const Formats& formats, const Config& config);
  /// The patent's constants (kept for callers that name only the normalisation).
  Rom38Table(const Formats& formats, Normalisation policy);
  /// The word at address `reg2` (register 2, n): s·K(n) in Formats::rom38.
  code_t k(code_t reg2) const { return words_[static_cast<std::size_t>(reg2) & mask_]; }
  /// The whole table, address 0 to 2^n_bits − 1, for reports and tests.
  const std::vector<code_t>& words() const { return words_; }

 private:
  std::vector<code_t> words_;
  std::size_t mask_;
};

// ---- Multiplier 39 -------------------------------------------------------------
/// register 9 × K(n), rounded to nearest, saturated to the norm format (between the
/// two passes register 9 holds up to ~16 000; that garbage saturates silently).
template <class FormatSet>
inline code_t mul39(const FormatSet& f, code_t reg9, code_t rom38_k) {
  if constexpr (FormatSet::compile_time) {
    // Both operands come from inside the device, within their formats (adder 8 wraps
    // register 9's input to S14.22; ROM 38 holds U8.16 words): no overflow check.
    static_assert(FormatSet::reg9.width() + FormatSet::rom38.width() <= 62, "product fits");
    return multiply_round_saturate_in_range<FormatSet::reg9.frac_bits + FormatSet::rom38.frac_bits -
                                            FormatSet::norm.frac_bits>(f.norm, reg9, rom38_k);
  } else {
    const int shift = f.reg9.frac_bits + f.rom38.frac_bits - f.norm.frac_bits;
    return multiply_round_saturate(f.norm, reg9, rom38_k, shift);
  }
}

// ---- Multipliers 13, 14, 15 ----------------------------------------------------
/// K·A × intensity (register 10, 11 or 12), rounded and saturated to the pin format.
template <class FormatSet>
inline code_t mul_rgb(const FormatSet& f, code_t norm39, code_t intensity) {
  if constexpr (FormatSet::compile_time) {
    // Multiplier 39 saturates K·A to its format, and Core::run, the only caller with
    // compile-time formats, refuses an intensity outside U8: no overflow check.
    static_assert(FormatSet::norm.width() + FormatSet::rgb.width() <= 62, "product fits");
    return multiply_round_saturate_in_range<FormatSet::norm.frac_bits - FormatSet::out.frac_bits>(
        f.out, norm39, intensity);
  } else {
    return multiply_round_saturate(f.out, norm39, intensity, f.norm.frac_bits - f.out.frac_bits);
  }
}

// ---- Squarer (design variant us5739820: US 5,739,820's repeated squaring) ---------
/// y² for a code y of the unsigned format U1.F (0 ≤ y ≤ 1): F fraction bits dropped,
/// rounding half up (multiply_round_saturate; y² ≤ 1 never saturates). rtl/design_space/squarer.v.
inline code_t square(const FixedFormat& format, code_t y) {
  return multiply_round_saturate(format, y, y, format.frac_bits);
}

}  // namespace arith
}  // namespace specular
