// Variant "schlick_divider": Schlick's rational cos^n by a restoring divider
// (variants/schlick_divider.h).
#include "specular/variants/schlick_divider.h"

#include "specular/variants/schlick.h"

namespace specular {
namespace variants {

SchlickDivider::SchlickDivider(const Config& config)
    : rom38_(Formats(schlick_config(config, "schlick_divider").widths), config) {}

code_t SchlickDivider::cos_power(code_t cos, code_t n) {
  // The divider's bits: floor(cos·2^23 / d), d ≥ 2^16 ≥ cos (cos·2^23 < 2^41).
  const std::uint64_t d = Schlick::denominator(cos, n);
  const std::uint64_t floor_quotient = (static_cast<std::uint64_t>(cos) << (quotient_bits - 1)) / d;
  return static_cast<code_t>((floor_quotient + 1) >> 1);
}

VariantResult SchlickDivider::run(const Operands& in) const {
  Schlick::check_operands(in, name());
  const DefaultFormats f;
  VariantResult result;
  result.lobe = arith::mul39(f, cos_power(in.cos, in.n), rom38_.k(in.n));
  for (std::size_t i = 0; i < 3; ++i) result.out[i] = arith::mul_rgb(f, result.lobe, in.rgb[i]);
  return result;
}

}  // namespace variants
}  // namespace specular
