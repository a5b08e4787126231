// Multipliers 13, 14, 15 of Fig. 1 alone: K·A × intensity → pins 24–26, within half
// an output LSB of the exact product; out-of-range values saturate silently.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "specular/datapath/multiplier_rgb.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockMul13To15, ChannelsScaleKATimesTheirIntensity) {
  const Formats f;
  Widths narrow_widths;
  narrow_widths.out_int_bits = 6;  // ±64: shows saturation at the pins
  const Formats narrow(narrow_widths);
  bus_signal norm{"norm"}, r{"r"}, g{"g"}, b{"b"}, out24{"out24"}, out25{"out25"}, out26{"out26"},
      out_narrow{"out_narrow"};
  MultiplierRgb mul13{"mul13", f}, mul14{"mul14", f}, mul15{"mul15", f};
  MultiplierRgb mul_narrow{"mul_narrow", narrow};
  mul13.norm(norm); mul13.intensity(r); mul13.out(out24);
  mul14.norm(norm); mul14.intensity(g); mul14.out(out25);
  mul15.norm(norm); mul15.intensity(b); mul15.out(out26);
  mul_narrow.norm(norm); mul_narrow.intensity(r); mul_narrow.out(out_narrow);

  std::mt19937 random(13);
  for (int i = 0; i < 300; ++i) {
    const double ka = std::uniform_real_distribution<double>(-40.0, 160.0)(random);
    const code_t ka_code = static_cast<code_t>(std::llround(std::ldexp(ka, f.norm.frac_bits)));
    const int ri = std::uniform_int_distribution<int>(0, 255)(random);
    const int gi = std::uniform_int_distribution<int>(0, 255)(random);
    const int bi = std::uniform_int_distribution<int>(0, 255)(random);
    norm.write(ka_code);
    r.write(ri);
    g.write(gi);
    b.write(bi);
    settle();
    const double k_a = f.norm.to_real(ka_code);
    EXPECT_NEAR(f.out.to_real(out24.read()), k_a * ri, f.out.lsb() / 2);
    EXPECT_NEAR(f.out.to_real(out25.read()), k_a * gi, f.out.lsb() / 2);
    EXPECT_NEAR(f.out.to_real(out26.read()), k_a * bi, f.out.lsb() / 2);
    const double narrow_max = narrow.out.to_real(narrow.out.max_code());
    const double narrow_min = narrow.out.to_real(narrow.out.min_code());
    const double clipped = std::min(std::max(k_a * ri, narrow_min), narrow_max);
    EXPECT_NEAR(narrow.out.to_real(out_narrow.read()), clipped, narrow.out.lsb() / 2);
  }
}

}  // namespace
}  // namespace specular
