/// \file
/// The exp2 unit (rtl/design_space/exp2_unit.v): 2^x for x ≤ 0, the usual hardware exp2 (Tang, ACM
/// TOMS 15(2), 1989; Oberman and Siu, "A high-performance area-efficient multifunction
/// interpolator", ARITH-17, 2005; Piñeiro, Oberman, Muller and Bruguera, IEEE Trans.
/// Computers 54(3), 2005): x splits into its integer part, a right shift, and its fraction
/// f ∈ [0, 1), whose 2^f ∈ [1, 2) comes from a table of 2^(i/2^A) and a linear
/// interpolation between neighbouring words. It is what a GPU's pow(c, n) does with
/// the log2 it already has: c^n = 2^(n·log2 c).
///
/// A block two variants could share, so it lives in a file pair of its own; its words are
/// written by specular_romgen into exp2.hex (one source for the table: this class).
#pragma once

#include <cstdint>
#include <vector>

#include "specular/format.h"

namespace specular {
namespace variants {

/// The unit's organisation. The defaults are exp2's (docs/variants/exp2.md argues them):
/// x and the result on register 9's format S14.22, 2^9 table words of 24 fraction bits.
struct Exp2Organisation {
  int x_frac_bits = 22;      ///< x's fraction bits (signed input: register 9's S14.22)
  int addr_bits = 9;         ///< A: the top A bits of f address the table (2^A words)
  int value_frac_bits = 24;  ///< V: fraction bits of a table value 2^(i/2^A) ∈ [1, 2)
  int out_frac_bits = 22;    ///< the result's fraction bits (register 9's format)
};

/// 2^x on integer codes: the table and the arithmetic of rtl/design_space/exp2_unit.v, bit for bit.
class Exp2Table {
 public:
  /// Fills the 2^addr_bits words for `organisation`.
  explicit Exp2Table(const Exp2Organisation& organisation = Exp2Organisation{});

  /// 2^x for an x code with x_frac_bits fraction bits, as a code with out_frac_bits,
  /// rounded half up; x ≥ 0 reads as 0 (result 1.0: the unit's domain is x ≤ 0).
  /// \code{.unparsed}
  ///   f = x mod 1, top A bits of f = address i, the other L = x_frac − A bits = t;
  ///   m = v_i + round(d_i·t / 2^L)       (2^f on V fraction bits, v_i = 2^(i/2^A))
  ///   result = round(m / 2^(V − out_frac − floor(x)))   (the integer part: a shift)
  /// \endcode
  code_t pow2(code_t x) const {
    if (x >= 0) x = 0;
    const code_t k = -(x >> org_.x_frac_bits);  // −floor(x) ≥ 0
    const std::uint64_t f = static_cast<std::uint64_t>(x) & f_mask_;
    const std::uint64_t word = words_[f >> low_bits_];
    const std::uint64_t value = (std::uint64_t{1} << org_.value_frac_bits) | (word >> delta_bits_);
    const std::uint64_t delta = word & delta_mask_;
    const std::uint64_t t = f & low_mask_;
    const std::uint64_t half = low_bits_ > 0 ? std::uint64_t{1} << (low_bits_ - 1) : 0;
    const std::uint64_t m = value + ((delta * t + half) >> low_bits_);
    // A shift past max_shift_ leaves 0 either way: the hardware saturates the amount.
    const code_t shift = k + org_.value_frac_bits - org_.out_frac_bits;
    const int s = static_cast<int>(shift < max_shift_ ? shift : max_shift_);
    return static_cast<code_t>((m + (std::uint64_t{1} << (s - 1))) >> s);
  }

  /// Word i = {v_i − 2^V (V bits), d_i = v_{i+1} − v_i (delta_bits)}, v_i =
  /// round(2^(i/2^A)·2^V), v_{2^A} = 2^(V+1): the image specular_romgen writes.
  const std::vector<std::uint64_t>& words() const { return words_; }
  /// Bits of a word's d_i field: those of the largest d_i.
  int delta_bits() const { return delta_bits_; }
  /// Bits of a whole word: V + delta_bits().
  int word_bits() const { return org_.value_frac_bits + delta_bits_; }
  /// The largest shift the hardware applies: V + 2 (any larger one also gives 0).
  int max_shift() const { return max_shift_; }
  /// The organisation the table was built for.
  const Exp2Organisation& organisation() const { return org_; }

 private:
  Exp2Organisation org_;
  int low_bits_;    ///< L = x_frac_bits − A: the interpolation fraction t's bits
  int delta_bits_;  ///< bits of the largest d_i
  int max_shift_;
  std::uint64_t f_mask_, low_mask_, delta_mask_;
  std::vector<std::uint64_t> words_;
};

}  // namespace variants
}  // namespace specular
