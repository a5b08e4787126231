// US 5,739,820's repeated squaring (see the header): base, k squarings, then the
// device's tail (ROM 38, multiplier 39, multipliers 13–15). Same bits as
// rtl/design_space/specular_us5739820.v.
#include "specular/variants/us5739820.h"

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace specular {
namespace variants {
namespace {

Config checked(const Config& config) {
  const Widths defaults{};
  for (const WidthField& field : width_fields())
    if (config.widths.*field.member != defaults.*field.member)
      throw std::invalid_argument("variant us5739820: width " + std::string(field.name) + " = " +
                                  std::to_string(config.widths.*field.member) +
                                  " (only the default " + std::to_string(defaults.*field.member) +
                                  " is built)");
  if (config.constants != Constants::patent)
    throw std::invalid_argument(std::string("variant us5739820: constants ") +
                                to_string(config.constants) + " (only patent: no pins 19/20 here)");
  if (config.saturation != Saturation::clamp)
    throw std::invalid_argument(std::string("variant us5739820: saturation ") +
                                to_string(config.saturation) + " (only clamp: the base is clamped at 0)");
  if (config.normalisation == Normalisation::device_energy)
    throw std::invalid_argument(
        "variant us5739820: normalisation device_energy (allowed: patent, energy, none; "
        "device_energy's K(n) normalises the patent device's own lobe)");
  return config;
}

}  // namespace

Us5739820::Us5739820(const Config& config)
    : formats_(checked(config).widths),
      rom38_(formats_, config) {}

namespace {

/// t_j = ⌈√2·2^j⌉, the smallest integer whose square reaches 2^(2j+1): n ≥ t_j exactly
/// when log2 n ≥ j + ½, so the count of t_j ≤ n is log2 n rounded (half up).
constexpr std::array<code_t, Us5739820::k_max> round_log2_thresholds() {
  std::array<code_t, Us5739820::k_max> t{};
  for (int j = 0; j < Us5739820::k_max; ++j) {
    code_t root = 1;
    while (root * root < (code_t{1} << (2 * j + 1))) ++root;
    t[static_cast<std::size_t>(j)] = root;
  }
  return t;
}

}  // namespace

int Us5739820::squarings(code_t n) {
  static constexpr std::array<code_t, k_max> thresholds = round_log2_thresholds();
  int k = 0;
  for (code_t t : thresholds) k += n >= t ? 1 : 0;
  return k;
}

code_t Us5739820::base(code_t cos, code_t n, int k) {
  constexpr int cos_frac = 16;  // register 1, U1.16
  const code_t one = code_t{1} << squarer_frac_bits;
  const code_t step = ((code_t{1} << cos_frac) - cos) * n;  // (1 − cos)·n, 16 fraction bits
  const code_t base = one - (step << (squarer_frac_bits - cos_frac - k));
  return base < 0 ? 0 : base;
}

code_t Us5739820::power(code_t cos, code_t n) {
  const int k = squarings(n);
  code_t y = base(cos, n, k);
  for (int i = 0; i < k; ++i) y = arith::square(squarer_format, y);
  return y;
}

code_t Us5739820::reg9(code_t cos, code_t n) const {
  return static_cast<code_t>(arith::round_shift(power(cos, n), squarer_frac_bits - formats_.reg9.frac_bits));
}

VariantResult Us5739820::run(const Operands& in) const {
  if (in.cos < 0 || in.cos > formats_.cos.max_code() || in.cos > (code_t{1} << formats_.cos.frac_bits))
    throw std::out_of_range("variant us5739820: cos code " + std::to_string(in.cos) + " (allowed 0..65536)");
  if (in.n < 0 || in.n > formats_.n.max_code())
    throw std::out_of_range("variant us5739820: n " + std::to_string(in.n) + " (allowed 0..1023)");
  for (code_t i : in.rgb)
    if (i < 0 || i > formats_.rgb.max_code())
      throw std::out_of_range("variant us5739820: intensity " + std::to_string(i) + " (allowed 0..255)");
  VariantResult r;
  r.lobe = arith::mul39(formats_, reg9(in.cos, in.n), rom38_.k(in.n));
  for (int c = 0; c < 3; ++c) r.out[c] = arith::mul_rgb(formats_, r.lobe, in.rgb[c]);
  return r;
}

}  // namespace variants
}  // namespace specular
