// The exp2 unit's table (specular/variants/exp2_unit.h): the one source of its words.
#include "specular/variants/exp2_unit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace specular {
namespace variants {

Exp2Table::Exp2Table(const Exp2Organisation& organisation) : org_(organisation) {
  const Exp2Organisation& o = org_;
  if (o.addr_bits < 1 || o.addr_bits > o.x_frac_bits || o.addr_bits > 16)
    throw std::invalid_argument("exp2 unit: addr_bits = " + std::to_string(o.addr_bits) +
                                " is outside [1, min(16, x_frac_bits = " +
                                std::to_string(o.x_frac_bits) + ")]");
  if (o.value_frac_bits <= o.out_frac_bits || o.value_frac_bits > 40)
    throw std::invalid_argument("exp2 unit: value_frac_bits = " + std::to_string(o.value_frac_bits) +
                                " is outside [out_frac_bits + 1 = " +
                                std::to_string(o.out_frac_bits + 1) + ", 40]");
  low_bits_ = o.x_frac_bits - o.addr_bits;
  max_shift_ = o.value_frac_bits + 2;
  const std::size_t count = std::size_t{1} << o.addr_bits;
  std::vector<std::uint64_t> v(count + 1);
  for (std::size_t i = 0; i <= count; ++i)
    v[i] = static_cast<std::uint64_t>(std::llround(
        std::ldexp(std::exp2(static_cast<double>(i) / static_cast<double>(count)), o.value_frac_bits)));
  std::uint64_t largest = 0;
  for (std::size_t i = 0; i < count; ++i) largest = std::max(largest, v[i + 1] - v[i]);
  delta_bits_ = 64 - __builtin_clzll(largest);
  f_mask_ = (std::uint64_t{1} << o.x_frac_bits) - 1;
  low_mask_ = (std::uint64_t{1} << low_bits_) - 1;
  delta_mask_ = (std::uint64_t{1} << delta_bits_) - 1;
  words_.resize(count);
  for (std::size_t i = 0; i < count; ++i)
    words_[i] = ((v[i] - (std::uint64_t{1} << o.value_frac_bits)) << delta_bits_) | (v[i + 1] - v[i]);
}

}  // namespace variants
}  // namespace specular
