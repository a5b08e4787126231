/// \file
/// Variant "schlick" (issue 26, docs/variants/schlick.md): cos^n λ by Schlick's rational
/// approximation x / (n − (n − 1)·x) (C. Schlick, Eurographics Rendering Workshop 1993;
/// Computer Graphics Forum 13(3), 1994) instead of the patent's two log2 passes, then
/// the device's tail: ROM 38's K(n), multiplier 39, multipliers 13–15.
/// Bit-accurate model of rtl/design_space/specular_schlick.v: the denominator d = n − (n − 1)·x
/// exactly (a 10 × 17-bit multiplier and a subtractor), d normalised by a leading-one
/// detector, 1/d by ReciprocalNr (table + one Newton–Raphson step), × x, rounded to
/// register 9's format S14.22.
#pragma once

#include <string_view>

#include "specular/arith.h"
#include "specular/core.h"
#include "specular/variants/reciprocal.h"
#include "specular/variants/variant.h"

namespace specular {
namespace variants {

/// The configuration Schlick's variants are built for: the default widths, the patent's
/// constants, the normalisations patent, energy and none (device_energy's K is the
/// patent lobe's own integral, not this one's); either saturation (the quotient is never
/// negative). Throws std::invalid_argument naming `variant`, anything else and what is
/// allowed.
const Config& schlick_config(const Config& config, std::string_view variant);

/// Variant "schlick": Schlick's x / (n − (n − 1)·x) by ReciprocalNr and a multiplier,
/// then ROM 38, multiplier 39 and multipliers 13–15.
class Schlick final : public Variant {
 public:
  /// Throws std::invalid_argument for a configuration it is not built for (schlick_config).
  explicit Schlick(const Config& config);
  std::string_view name() const override { return "schlick"; }
  VariantResult run(const Operands& in) const override;

  /// The denominator d = n − (n − 1)·x as a U10.16 code: n·2^16 − (n − 1)·cos, exact
  /// (rtl/design_space/schlick_denominator.v).
  static std::uint64_t denominator(code_t cos, code_t n);
  /// Throws std::out_of_range unless cos is 0 … 2^16 and n 1 … 1000 (register 1's and 2's).
  static void check_operands(const Operands& in, std::string_view variant);
  /// x / d, Schlick's cos^n λ, as a register-9 code (S14.22): round(cos·y1 / 2^(shift)).
  code_t cos_power(code_t cos, code_t n) const;

  static constexpr int denominator_bits = 26;  ///< U10.16: n ≤ 1023 times 2^16

 private:
  ReciprocalNr reciprocal_;
  arith::Rom38Table rom38_;
};

}  // namespace variants
}  // namespace specular
