// arith.h's bus helpers and the per-block functions as pure functions (no kernel):
// wrap to a width, saturate (silently, downstream of register 9), round half up,
// and the contents of ROM 5 and ROM 38 against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "specular/arith.h"
#include "specular/reference.h"

namespace specular {
namespace {

constexpr double two_pi = 6.283185307179586476925286766559;

TEST(ArithBus, WrapKeepsTheLowBitsAsTwosComplement) {
  const FixedFormat s8{true, 3, 4};   // 8 bits, −128 .. 127
  EXPECT_EQ(arith::wrap(s8, 127), 127);
  EXPECT_EQ(arith::wrap(s8, 128), -128);
  EXPECT_EQ(arith::wrap(s8, -129), 127);
  EXPECT_EQ(arith::wrap(s8, -1), -1);
  EXPECT_EQ(arith::wrap(s8, 256 + 5), 5);
  const FixedFormat u8{false, 8, 0};  // 0 .. 255
  EXPECT_EQ(arith::wrap(u8, 256), 0);
  EXPECT_EQ(arith::wrap(u8, -1), 255);
  const Formats f;                    // register 9's bus: S14.22, 37 bits
  const code_t span = code_t{1} << 37;
  EXPECT_EQ(arith::wrap(f.reg9, f.reg9.max_code() + 1), f.reg9.min_code());
  EXPECT_EQ(arith::wrap(f.reg9, 12345 + 3 * span), 12345);
  EXPECT_EQ(arith::wrap(f.reg9, -12345 - span), -12345);
}

TEST(ArithBus, SaturateClipsToTheFormatsRange) {
  const FixedFormat s8{true, 3, 4};
  EXPECT_EQ(arith::saturate(s8, 1000), 127);
  EXPECT_EQ(arith::saturate(s8, -1000), -128);
  EXPECT_EQ(arith::saturate(s8, 42), 42);
  const FixedFormat u8{false, 8, 0};
  EXPECT_EQ(arith::saturate(u8, -3), 0);
  EXPECT_EQ(arith::saturate(u8, static_cast<__int128>(1) << 100), 255);
}

TEST(ArithBus, RoundShiftRoundsHalfUp) {
  EXPECT_EQ(arith::round_shift(5, 1), 3);    //  2.5  →  3
  EXPECT_EQ(arith::round_shift(-5, 1), -2);  // −2.5  → −2
  EXPECT_EQ(arith::round_shift(4, 1), 2);
  EXPECT_EQ(arith::round_shift(7, 2), 2);    //  1.75 →  2
  EXPECT_EQ(arith::round_shift(5, 2), 1);    //  1.25 →  1
  EXPECT_EQ(arith::round_shift(6, 2), 2);    //  1.5  →  2
  EXPECT_EQ(arith::round_shift(-6, 2), -1);  // −1.5  → −1
  EXPECT_EQ(arith::round_shift(-7, 2), -2);  // −1.75 → −2
  EXPECT_EQ(arith::round_shift(9, 0), 9);
  EXPECT_EQ(arith::round_shift(3, -4), 48);
}

// ROM 5's mantissa table against the closed form log2(1 + a/2^M), within half a word LSB.
TEST(ArithRom5, EveryWordIsLog2OfItsMantissa) {
  const Formats f;
  const arith::Rom5Table rom(f);
  const int M = f.widths.rom5_addr_bits;
  const int W = f.widths.rom5_word_bits;
  ASSERT_EQ(rom.words().size(), std::size_t{1} << M);
  for (std::size_t a = 0; a < rom.words().size(); ++a) {
    const double want = std::log2(1.0 + std::ldexp(static_cast<double>(a), -M));
    ASSERT_NEAR(std::ldexp(static_cast<double>(rom.words()[a]), -W), want, std::ldexp(0.5, -W))
        << "word " << a;
  }
}

// Every cos code fits ROM 5's address after the leading one, so pass 1 reads log2 cos λ
// to half a word LSB; log2 0 is −F (spec, Decision "log2 0").
TEST(ArithRom5, Log2OfEveryCosCodeIsWithinHalfAWordLsb) {
  const Formats f;
  const arith::Rom5Table rom(f);
  const double half_lsb = std::ldexp(0.5, -f.widths.rom5_word_bits);
  EXPECT_EQ(rom.log2(arith::mux3(f, false, 0, 0)), -(code_t{16} << f.log2.frac_bits));
  EXPECT_DOUBLE_EQ(f.log2.to_real(rom.log2(0)), -16.0);
  for (code_t c = 1; c <= f.cos.one(); ++c) {
    const code_t bus = arith::mux3(f, false, c, 0);
    const double got = f.log2.to_real(rom.log2(bus));
    ASSERT_NEAR(got, std::log2(f.cos.to_real(c)), half_lsb + 1e-15) << "cos code " << c;
  }
}

// Pass 2 reads log2 of register 9 (1 … ~16 000): the mantissa is cut to M bits, so the
// error is at most log2(1 + 2^-M) plus half a word LSB.
TEST(ArithRom5, Log2OfRegister9ValuesIsWithinTheMantissaBound) {
  const Formats f;
  const arith::Rom5Table rom(f);
  const double bound = std::log2(1.0 + std::ldexp(1.0, -f.widths.rom5_addr_bits)) +
                       std::ldexp(0.5, -f.widths.rom5_word_bits);
  double worst = 0.0;
  for (double v = 1.0; v < 16384.0; v = v * (1.0 + std::ldexp(1.0, -14)) + 1e-9) {
    const code_t bus = static_cast<code_t>(std::ldexp(v, f.reg9.frac_bits));
    const double got = f.log2.to_real(rom.log2(bus));
    const double want = std::log2(f.reg9.to_real(bus));
    worst = std::max(worst, std::fabs(got - want));
    ASSERT_NEAR(got, want, bound) << "register 9 = " << f.reg9.to_real(bus);
  }
  EXPECT_GT(worst, 0.0);
  // The largest value register 9 can hold still reads a finite log2 below reg9_int_bits.
  EXPECT_LT(f.log2.to_real(rom.log2(f.reg9.max_code())), f.widths.reg9_int_bits);
  EXPECT_NEAR(f.log2.to_real(rom.log2(f.reg9.max_code())), f.widths.reg9_int_bits, bound);
}

TEST(ArithRom38, EveryWordIsKOfNUnderEachPolicy) {
  const Formats f;
  const double half_lsb = std::ldexp(0.5, -f.rom38.frac_bits);
  const arith::Rom38Table patent(f, Normalisation::patent);
  const arith::Rom38Table energy(f, Normalisation::energy);
  const arith::Rom38Table none(f, Normalisation::none);
  for (code_t n = 1; n <= 1000; ++n) {
    ASSERT_NEAR(f.rom38.to_real(patent.k(n)), two_pi / (n + 2.0), half_lsb) << n;
    ASSERT_NEAR(f.rom38.to_real(energy.k(n)), (n + 2.0) / two_pi, half_lsb) << n;
    ASSERT_EQ(f.rom38.to_real(none.k(n)), 1.0) << n;
  }
  EXPECT_NEAR(f.rom38.to_real(energy.k(1000)), 159.47, 0.01);  // ≈ 160, issue 2 item 3
  EXPECT_NEAR(f.rom38.to_real(patent.k(1)), 2.0944, 1e-4);
}

// Between the two passes register 9 holds 1 − n·log2 cos λ (up to ~16 000):
// multipliers 39 and 13–15 must take it silently (saturate), never fail.
TEST(ArithDownstream, Register9GarbageSaturatesSilently) {
  const Formats f;
  const code_t pass1_max = static_cast<code_t>(std::ldexp(16001.0, f.reg9.frac_bits));
  const code_t k_energy = static_cast<code_t>(std::ldexp(159.47, f.rom38.frac_bits));
  EXPECT_EQ(arith::mul39(f, pass1_max, k_energy), f.norm.max_code());
  EXPECT_EQ(arith::mul39(f, f.reg9.max_code(), f.rom38.max_code()), f.norm.max_code());
  EXPECT_EQ(arith::mul39(f, f.reg9.min_code(), f.rom38.max_code()), f.norm.min_code());
  // The largest K·A (≈ 1024) times the largest intensity still fits the pins' S18.13.
  EXPECT_NEAR(f.out.to_real(arith::mul_rgb(f, f.norm.max_code(), f.rgb.max_code())),
              f.norm.to_real(f.norm.max_code()) * 255.0, f.out.lsb() / 2);
  Widths narrow;
  narrow.out_int_bits = 4;  // ±16: K·A·I = 255 does not fit
  const Formats n(narrow);
  EXPECT_EQ(arith::mul_rgb(n, n.norm.one(), 255), n.out.max_code());
  EXPECT_EQ(arith::mul_rgb(n, -n.norm.one(), 255), n.out.min_code());
}

// Multiplier 39 and multipliers 13–15 round to nearest: within half an output LSB.
TEST(ArithDownstream, MultipliersRoundToNearest) {
  const Formats f;
  for (double a : {0.0, 0.001, 0.3333333, 0.7071, 1.0, -0.25, -6.1}) {
    for (double k : {2.0944, 0.00625, 1.0, 159.47}) {
      const code_t a_code = static_cast<code_t>(std::llround(std::ldexp(a, f.reg9.frac_bits)));
      const code_t k_code = static_cast<code_t>(std::llround(std::ldexp(k, f.rom38.frac_bits)));
      const double exact = f.reg9.to_real(a_code) * f.rom38.to_real(k_code);
      if (std::fabs(exact) >= f.norm.to_real(f.norm.max_code())) continue;
      const code_t norm = arith::mul39(f, a_code, k_code);
      EXPECT_NEAR(f.norm.to_real(norm), exact, f.norm.lsb() / 2) << a << " × " << k;
      for (code_t i : {0, 1, 77, 255}) {
        const double out = f.out.to_real(arith::mul_rgb(f, norm, i));
        EXPECT_NEAR(out, f.norm.to_real(norm) * i, f.out.lsb() / 2) << a << " × " << k << " × " << i;
      }
    }
  }
}

}  // namespace
}  // namespace specular
