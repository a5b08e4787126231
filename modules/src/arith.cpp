#include "specular/arith.h"

#include <cmath>

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

Rom38Table::Rom38Table(const Formats& f, Normalisation policy)
    : words_(static_cast<std::size_t>(f.rom38_words())), mask_(words_.size() - 1) {
  for (std::size_t n = 0; n < words_.size(); ++n) {
    const double k = reference::k(static_cast<unsigned>(n), policy);
    words_[n] = saturate(f.rom38, std::llround(std::ldexp(k, f.rom38.frac_bits)));
  }
}

}  // namespace arith
}  // namespace specular
