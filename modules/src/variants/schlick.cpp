// Variant "schlick": Schlick's rational cos^n (variants/schlick.h).
#include "specular/variants/schlick.h"

#include <stdexcept>
#include <string>

namespace specular {
namespace variants {

const Config& schlick_config(const Config& config, std::string_view variant) {
  const std::string name(variant);
  const Widths defaults{};
  for (const WidthField& field : width_fields())
    if (config.widths.*field.member != defaults.*field.member)
      throw std::invalid_argument(name + ": width " + field.name + " = " +
                                  std::to_string(config.widths.*field.member) +
                                  " is not built (allowed: the default, " + field.name + " = " +
                                  std::to_string(defaults.*field.member) + ")");
  if (config.constants != Constants::patent)
    throw std::invalid_argument(name + ": constants '" + to_string(config.constants) +
                                "' are not built (allowed: patent; no pins 19/20 here, s = 1)");
  if (config.normalisation == Normalisation::device_energy)
    throw std::invalid_argument(name + ": normalisation '" + to_string(config.normalisation) +
                                "' is not built (allowed: patent, energy, none; its K is the patent "
                                "lobe's own integral)");
  return config;
}

Schlick::Schlick(const Config& config)
    : rom38_(Formats(schlick_config(config, "schlick").widths), config) {}

std::uint64_t Schlick::denominator(code_t cos, code_t n) {
  return (static_cast<std::uint64_t>(n) << DefaultFormats::cos.frac_bits) -
         static_cast<std::uint64_t>(n - 1) * static_cast<std::uint64_t>(cos);
}

code_t Schlick::cos_power(code_t cos, code_t n) const {
  // d = m·2^(msb − 16) with m ∈ [1, 2): x/d = cos·(1/m)·2^−msb, so with y1 = 2^26/m the
  // code cos·y1·2^(22 − msb − 26) is rounded half up at shift msb + 4 (20 … 29).
  const arith::LeadingOne d = arith::leading_one(denominator(cos, n), denominator_bits);
  const std::uint64_t y1 = reciprocal_.reciprocal(d.normalised);
  const int shift = d.msb + ReciprocalNr::frac_bits - DefaultFormats::reg9.frac_bits;
  const std::uint64_t product = static_cast<std::uint64_t>(cos) * y1;  // < 2^43
  return static_cast<code_t>((product + (std::uint64_t{1} << (shift - 1))) >> shift);
}

void Schlick::check_operands(const Operands& in, std::string_view variant) {
  if (in.n < 1 || in.n > 1000 || in.cos < 0 || in.cos > (code_t{1} << DefaultFormats::cos.frac_bits))
    throw std::out_of_range(std::string(variant) + ": operands cos code " + std::to_string(in.cos) +
                            ", n " + std::to_string(in.n) + " outside cos 0..65536, n 1..1000");
}

VariantResult Schlick::run(const Operands& in) const {
  check_operands(in, name());
  const DefaultFormats f;
  VariantResult result;
  result.lobe = arith::mul39(f, cos_power(in.cos, in.n), rom38_.k(in.n));
  for (std::size_t i = 0; i < 3; ++i) result.out[i] = arith::mul_rgb(f, result.lobe, in.rgb[i]);
  return result;
}

}  // namespace variants
}  // namespace specular
