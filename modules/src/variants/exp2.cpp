// Variant exp2: ROM 5 → multiplier 6 (× n) → exp2 unit → ROM 38 / multiplier 39 →
// multipliers 13–15, each an arith.h block function or the exp2 unit (rtl/design_space/specular_exp2.v).
#include "specular/variants/exp2.h"

#include <stdexcept>
#include <string>

namespace specular {
namespace variants {
namespace {

/// The configuration exp2 is built for, or std::invalid_argument naming what is not.
const Config& checked(const Config& config) {
  const Widths defaults{};
  for (const WidthField& field : width_fields())
    if (config.widths.*field.member != defaults.*field.member)
      throw std::invalid_argument("variant exp2: width " + std::string(field.name) + " = " +
                                  std::to_string(config.widths.*field.member) +
                                  " (only the default widths are built: " + field.name + " = " +
                                  std::to_string(defaults.*field.member) + ")");
  if (config.constants != Constants::patent)
    throw std::invalid_argument(std::string("variant exp2: constants '") + to_string(config.constants) +
                                "' (allowed: patent; exp2 has no pins 19/20 and s = 1)");
  if (config.normalisation == Normalisation::device_energy)
    throw std::invalid_argument(std::string("variant exp2: normalisation '") +
                                to_string(config.normalisation) +
                                "' (allowed: patent, energy, none; device-energy integrates the "
                                "patent device's own lobe)");
  return config;
}

}  // namespace

Exp2Variant::Exp2Variant(const Config& config)
    : config_(checked(config)), formats_(config_.widths), rom5_(formats_), rom38_(formats_, config_) {}

code_t Exp2Variant::exponent(const Operands& in) const {
  const DefaultFormats f;
  const code_t log2 = rom5_.log2(f, arith::mux3(f, false, in.cos, 0));
  return arith::mul6(f, log2, arith::mux4(f, false, in.n, 0));
}

VariantResult Exp2Variant::run(const Operands& in) const {
  // The compile-time multipliers skip overflow checks: operands must be on their buses.
  const DefaultFormats f;
  if (in.cos < 0 || in.cos > f.cos.one() || in.n < 0 || in.n > f.n.max_code())
    throw std::out_of_range("variant exp2: cos code " + std::to_string(in.cos) + " or n " +
                            std::to_string(in.n) + " outside [0, " + std::to_string(f.cos.one()) + "], [0, " +
                            std::to_string(f.n.max_code()) + "]");
  for (code_t intensity : in.rgb)
    if (intensity < 0 || intensity > f.rgb.max_code())
      throw std::out_of_range("variant exp2: intensity " + std::to_string(intensity) + " outside [0, " +
                              std::to_string(f.rgb.max_code()) + "]");
  VariantResult r;
  r.lobe = arith::mul39(f, cos_pow_n(in), rom38_.k(in.n));
  for (int ch = 0; ch < 3; ++ch) r.out[ch] = arith::mul_rgb(f, r.lobe, in.rgb[ch]);
  return r;
}

}  // namespace variants
}  // namespace specular
