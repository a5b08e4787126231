/// \file
/// The reciprocal unit of the design variants that divide (schlick): 1/m of a divisor
/// normalised to m ∈ [1, 2) by a leading-one detector (arith::leading_one), read from a
/// small table at m's first fraction bits and refined by one Newton–Raphson step
/// y1 = y0·(2 − m·y0), which squares the table's relative error. Bit-accurate model of
/// rtl/design_space/reciprocal_nr.v; the table is the image specular_romgen writes (recip.hex).
///
/// Sizes (docs/variants/schlick.md): a table word is within 2^-11 of 1/m relatively, so
/// one step leaves 1 − m·y1 = e0² ∈ [0, 2^-22]; a bias of 2^-23 centres that one-sided
/// error, so y1 is within ±2^-23 (plus rounding) of 1/m: 1024 words where an unbiased
/// step needs 2048 for the same quotient error.
#pragma once

#include <cstdint>
#include <vector>

namespace specular {
namespace variants {

/// 1/m by a 1024-word table and one Newton–Raphson step (rtl/design_space/reciprocal_nr.v).
class ReciprocalNr {
 public:
  static constexpr int mantissa_bits = 26;    ///< the divisor m as U1.25, leading one at bit 25
  static constexpr int addr_bits = 10;        ///< table address: m's first 10 fraction bits
  static constexpr int word_bits = 13;        ///< table word y0 ≈ 1/m at the interval's middle, U0.13
  static constexpr int error_frac_bits = 28;  ///< e0 = 1 − m·y0 kept to 2^-28 (floor)
  static constexpr int frac_bits = 26;        ///< the result y1 ≈ 1/m, U0.26
  static constexpr int bias = 8;              ///< 2^-23 added to y1 (in 2^-26 units)

  /// Fills the table (2^addr_bits words of word_bits).
  ReciprocalNr();
  /// y1 ≈ 2^frac_bits / m for a mantissa code with its leading one at bit 25.
  std::uint64_t reciprocal(std::uint64_t mantissa) const;
  /// Word a = round(2^13 / (1 + (a + ½)/2^10)): 1/m at the middle of the a-th interval.
  const std::vector<std::uint32_t>& words() const { return words_; }

 private:
  std::vector<std::uint32_t> words_;
};

}  // namespace variants
}  // namespace specular
