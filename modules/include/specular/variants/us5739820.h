/// \file
/// Design variant us5739820 (issue 26, docs/variants/us5739820.md): cos^n λ as in US
/// patent 5,739,820 (Lentz, 1998), (1 − (1 − cos λ)·n/2^k)^(2^k), the base clamped at 0
/// and raised to 2^k by k successive squarings in one squarer (arith::square,
/// rtl/design_space/squarer.v). k = round(log2 n), so that 2^k is the power of two nearest to n
/// (exact for n a power of two). The result, rounded to register 9's format S14.22,
/// goes through ROM 38 and multiplier 39, then multipliers 13–15, as in the device.
/// rtl/design_space/specular_us5739820.v is this model in Verilog: one start every k + 1 clocks.
#pragma once

#include <string_view>

#include "specular/arith.h"
#include "specular/variants/variant.h"

namespace specular {
namespace variants {

/// Variant "us5739820": cos^n ≈ (1 − (1 − cos)·n/2^k)^(2^k) by k squarings in one
/// squarer (US 5,739,820), then the device's tail.
class Us5739820 final : public Variant {
 public:
  /// The squarer's fraction bits: the base 1 − x·n·2^−(16+k) is exact on them
  /// (16 + k ≤ 26) and k ≤ 10 roundings cost at most 2^(k−F−1) ≤ 2^−21 of cos^n.
  static constexpr int squarer_frac_bits = 30;
  /// The squarer's format, U1.30: cos^n ∈ [0, 1].
  static constexpr FixedFormat squarer_format{false, 1, squarer_frac_bits};
  /// Largest number of squarings (n ≤ 1023 on register 2's bus: round(log2 1023) = 10).
  static constexpr int k_max = 10;

  /// Throws std::invalid_argument naming the value and what is allowed for widths
  /// other than the defaults, constants other than the patent's, Saturation::literal
  /// or Normalisation::device_energy (that K(n) normalises the device's own lobe).
  explicit Us5739820(const Config& config);
  std::string_view name() const override { return "us5739820"; }
  /// Throws std::out_of_range for a code outside its input bus.
  VariantResult run(const Operands& in) const override;

  /// k = round(log2 n): the number of squarings, the count of thresholds t_j ≤ n,
  /// t_j the smallest integer with t_j² ≥ 2^(2j+1) (√2·2^j rounded up). n = 0 gives 0.
  static int squarings(code_t n);
  /// The base max(0, 1 − (1 − cos)·n/2^k) as a U1.30 code (exact).
  static code_t base(code_t cos, code_t n, int k);
  /// cos^n ≈ base^(2^k) as a U1.30 code: k squarings of the base.
  static code_t power(code_t cos, code_t n);
  /// power() rounded half up to register 9's format S14.22: multiplier 39's operand.
  code_t reg9(code_t cos, code_t n) const;

 private:
  Formats formats_;
  arith::Rom38Table rom38_;
};

}  // namespace variants
}  // namespace specular
