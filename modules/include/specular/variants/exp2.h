/// \file
/// Variant exp2 (docs/variants/exp2.md): cos^n as a GPU's pow computes it,
/// cos^n = 2^(n·log2 cos): ROM 5's log2 times n as multiplier 6 does in pass 1 (without
/// adder 8), then the exp2 unit (table of 2^f plus linear interpolation, the integer
/// part a shift) gives cos^n on register 9's format S14.22; ROM 38, multiplier 39 and
/// multipliers 13–15 follow as in the device. Verilog: rtl/design_space/specular_exp2.v.
#pragma once

#include <string_view>

#include "specular/arith.h"
#include "specular/core.h"
#include "specular/variants/exp2_unit.h"
#include "specular/variants/variant.h"

namespace specular {
namespace variants {

/// Variant "exp2": cos^n = 2^(n·log2 cos) through ROM 5, multiplier 6 and the exp2
/// unit (Exp2Table), then the device's tail (see exp2.h).
class Exp2Variant final : public Variant {
 public:
  /// Takes the default widths, constants patent (s = 1) and the normalisations patent,
  /// energy and none (ROM 38's banks 0–2); either saturation (the lobe is never negative).
  /// Throws std::invalid_argument naming anything else and what is allowed.
  explicit Exp2Variant(const Config& config);
  std::string_view name() const override { return "exp2"; }
  VariantResult run(const Operands& in) const override;

  /// x = n·log2 cos on register 9's format: ROM 5, then multiplier 6 with n (pass 1).
  code_t exponent(const Operands& in) const;
  /// cos^n on register 9's format: the exp2 unit's 2^x, and 0 for a zero cos code, as a
  /// shader's pow(0, n) = exp2(n·log2 0) = exp2(−∞) = 0 (ROM 5 reads log2 0 as −16, which
  /// would leave 2^−16n: 2^−16·K(1) = 33 lobe LSBs at n = 1).
  code_t cos_pow_n(const Operands& in) const { return in.cos == 0 ? 0 : exp2_.pow2(exponent(in)); }
  /// The exp2 unit's table and arithmetic.
  const Exp2Table& exp2_table() const { return exp2_; }

 private:
  Config config_;
  Formats formats_;
  arith::Rom5Table rom5_;
  arith::Rom38Table rom38_;
  Exp2Table exp2_;
};

}  // namespace variants
}  // namespace specular
