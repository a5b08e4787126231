// The reciprocal unit: table + one Newton–Raphson step (variants/reciprocal.h).
#include "specular/variants/reciprocal.h"

#include <stdexcept>
#include <string>

namespace specular {
namespace variants {

ReciprocalNr::ReciprocalNr() : words_(std::size_t{1} << addr_bits) {
  // 2^13 / (1 + (a + ½)/2^10) = 2^25 / (2^11 + 2a + 1), rounded to nearest (the divisor
  // is odd: no ties), in integers so the image does not depend on the host's libm.
  const std::uint64_t numerator = std::uint64_t{1} << (word_bits + addr_bits + 1);
  for (std::size_t a = 0; a < words_.size(); ++a) {
    const std::uint64_t divisor = (std::uint64_t{1} << (addr_bits + 1)) + 2 * a + 1;
    words_[a] = static_cast<std::uint32_t>((2 * numerator + divisor) / (2 * divisor));
  }
}

std::uint64_t ReciprocalNr::reciprocal(std::uint64_t mantissa) const {
  if (mantissa >> (mantissa_bits - 1) != 1)
    throw std::invalid_argument("ReciprocalNr: mantissa " + std::to_string(mantissa) +
                                " does not have its leading one at bit " + std::to_string(mantissa_bits - 1));
  const int mantissa_frac = mantissa_bits - 1;
  const std::uint64_t address = (mantissa >> (mantissa_frac - addr_bits)) & ((1u << addr_bits) - 1);
  const std::int64_t y0 = words_[address];
  // e0 = 1 − m·y0 exactly (2^-38 units), then floor to 2^-28: |e0| < 2^-10.
  const std::int64_t one = std::int64_t{1} << (mantissa_frac + word_bits);
  const std::int64_t e0 = one - static_cast<std::int64_t>(mantissa) * y0;
  const std::int64_t e0_kept = e0 >> (mantissa_frac + word_bits - error_frac_bits);
  // y0·e0 to 2^-26, rounding half up; y1 = y0 + y0·e0 + bias.
  const int shift = word_bits + error_frac_bits - frac_bits;
  const std::int64_t correction = (y0 * e0_kept + (std::int64_t{1} << (shift - 1))) >> shift;
  return static_cast<std::uint64_t>((y0 << (frac_bits - word_bits)) + correction + bias);
}

}  // namespace variants
}  // namespace specular
