#include "specular/arith.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "specular/constants.h"
#include "specular/core.h"
#include "specular/reference.h"

namespace specular {
namespace arith {

Rom5Table::Rom5Table(const Formats& f)
    : words_(static_cast<std::size_t>(f.rom5_words())),
      addr_bits_(f.widths.rom5_addr_bits),
      word_bits_(f.log2.frac_bits),
      bus_frac_bits_(f.reg9.frac_bits) {
  for (std::size_t a = 0; a < words_.size(); ++a) {
    const double mantissa = 1.0 + std::ldexp(static_cast<double>(a), -addr_bits_);
    words_[a] = static_cast<std::uint32_t>(std::llround(std::ldexp(std::log2(mantissa), word_bits_)));
  }
  // log2 0 := log2 of the smallest cos code, −F (spec, Decision "log2 0").
  zero_log2_ = -(static_cast<code_t>(f.cos.frac_bits) << word_bits_);
}

double register9_lobe_integral(const Formats& f, const Rom5Table& rom5, code_t pin19_h,
                               code_t pin20_a, code_t n) {
  // From cos = 1 down: register 9 after pass 2 never grows as cos falls (every block
  // on the path is monotone), so the first clamped zero ends the lobe.
  double sum = 0;
  for (code_t c = f.cos.one(); c >= 0; --c) {
    const code_t reg9 = pass(f, rom5, Saturation::clamp, pin19_h, pin20_a, false, c, 0, n);
    const code_t a = pass(f, rom5, Saturation::clamp, pin19_h, pin20_a, true, c, reg9, n);
    if (a <= 0) break;
    sum += f.reg9.to_real(a) * reference::code_interval_integral(c, f.cos.frac_bits);
  }
  return sum;
}

Rom38Table::Rom38Table(const Formats& f, Normalisation policy)
    : Rom38Table(f, Config{f.widths, policy}) {}

Rom38Table::Rom38Table(const Formats& f, const Config& config)
    : words_(static_cast<std::size_t>(f.rom38_words())), mask_(words_.size() - 1) {
  std::optional<Rom5Table> rom5;
  if (config.normalisation == Normalisation::device_energy) rom5.emplace(f);
  for (std::size_t n = 0; n < words_.size(); ++n) {
    const double k =
        config.normalisation == Normalisation::device_energy
            ? 1.0 / register9_lobe_integral(f, *rom5, pin19_code(f, config.constants),
                                            pin20_code(f, config.constants), static_cast<code_t>(n))
            : reference::k(static_cast<unsigned>(n), config.normalisation, config.constants);
    const long long word = std::llround(std::ldexp(k, f.rom38.frac_bits));
    if (word > f.rom38.max_code()) {
      std::ostringstream m;
      m << "ROM 38 word for n = " << n << " is " << k << ", above the largest " << f.rom38.name()
        << " value " << f.rom38.to_real(f.rom38.max_code()) << " (normalisation "
        << to_string(config.normalisation) << ", constants " << to_string(config.constants)
        << "): widen rom38_int_bits";
      throw std::invalid_argument(m.str());
    }
    words_[n] = word;
  }
  // Under `literal` a result may be negative: the most negative register 9 holds for
  // n (a − h·log2(a + n·F) at cos code 0) times the word must stay inside multiplier
  // 39's format, or results would saturate. Only device-energy × patent constants
  // breaks this (−1178 at n = 1000, below S10.20's −1024): refused, never clamped.
  if (config.saturation == Saturation::literal) {
    const ConstantValues& c = constant_values(config.constants);
    for (unsigned n = n_min; n <= n_max; ++n) {
      const double lowest =
          (c.a() - c.h() * std::log2(c.a() + static_cast<double>(n) * f.cos.frac_bits)) *
          f.rom38.to_real(words_[n & mask_]);
      if (lowest < f.norm.to_real(f.norm.min_code())) {
        std::ostringstream m;
        m << "saturation literal with normalisation " << to_string(config.normalisation)
          << " and constants " << to_string(config.constants) << " gives K·A = " << lowest
          << " at n = " << n << ", below multiplier 39's " << f.norm.name() << " minimum "
          << f.norm.to_real(f.norm.min_code()) << "; use saturation clamp or other constants";
        throw std::invalid_argument(m.str());
      }
    }
  }
}

}  // namespace arith
}  // namespace specular
