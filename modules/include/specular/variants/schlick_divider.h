/// \file
/// Variant "schlick_divider" (issue 26, docs/variants/schlick.md): Schlick's rational
/// cos^n x / (n − (n − 1)·x) as variant schlick, the quotient by a restoring divider, one
/// bit per clock (rtl/design_space/restoring_divider.v), instead of a reciprocal table and
/// multipliers. A restoring divider's 24 bits are floor(cos·2^23 / d) exactly, so register
/// 9 = (that + 1) / 2 is x/d rounded half up to S14.22: within ½ LSB of the formula.
/// Bit-accurate model of rtl/design_space/specular_schlick_divider.v.
#pragma once

#include <string_view>

#include "specular/arith.h"
#include "specular/core.h"
#include "specular/variants/variant.h"

namespace specular {
namespace variants {

/// Variant "schlick_divider": Schlick's quotient by a restoring divider, one bit a clock.
class SchlickDivider final : public Variant {
 public:
  /// Throws std::invalid_argument for a configuration it is not built for (schlick_config).
  explicit SchlickDivider(const Config& config);
  std::string_view name() const override { return "schlick_divider"; }
  VariantResult run(const Operands& in) const override;

  /// x / d as a register-9 code (S14.22), rounded half up.
  static code_t cos_power(code_t cos, code_t n);

  static constexpr int quotient_bits = 24;  ///< the divider's bits: 2^0 … 2^-23

 private:
  arith::Rom38Table rom38_;
};

}  // namespace variants
}  // namespace specular
