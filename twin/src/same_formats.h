// Whether two width sets give the same bus formats: the check that a Config matches
// the widths a model was verilated with (rtl/ takes its widths as parameters).
#pragma once

#include "specular/format.h"

namespace specular {

inline bool same_formats(const Widths& a, const Widths& b) {
  const Formats fa{a}, fb{b};
  const auto same = [](const FixedFormat& x, const FixedFormat& y) {
    return x.is_signed == y.is_signed && x.int_bits == y.int_bits && x.frac_bits == y.frac_bits;
  };
  return same(fa.cos, fb.cos) && same(fa.n, fb.n) && same(fa.rgb, fb.rgb) &&
         same(fa.mux4, fb.mux4) && same(fa.log2, fb.log2) && same(fa.reg9, fb.reg9) &&
         same(fa.rom38, fb.rom38) && same(fa.norm, fb.norm) && same(fa.out, fb.out) &&
         a.rom5_addr_bits == b.rom5_addr_bits;
}

}  // namespace specular
