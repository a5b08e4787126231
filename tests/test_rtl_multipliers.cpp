// Multipliers 13–15 verilated alone (rtl/device/multiplier_rgb.v at the default widths,
// twin/multipliers.cmake) against arith::mul_rgb (issue 13, must-have 5), × all 256
// intensities each:
//  - every distinct K·A value — multiplier 39's output code — that the
//    `specular_tb --sweep` grid produces under each of the six policy combinations
//    (Core over the grid testbench/input.h defines: n 1..1000 × sweep_cos_codes);
//  - K·A codes the sweep never gives: around 0 and the format's ends, and random codes
//    over the whole 31-bit input. At these widths no input saturates (|K·A| ≤ 2^30,
//    × 255 < 2^38 = the pin range × 2^7); the formal proof (rtl/formal/) covers the
//    saturation logic.
// Every product is also checked against the rounding and saturation written out here
// on 128 bits, so a fault shared by mul_rgb and the RTL would show too. About 8 s of
// CPU in all (docs/rtl.md): quick.
#include <gtest/gtest.h>

#include <Vmultiplier_rgb.h>
#include <verilated.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "input.h"
#include "rtl_coverage.h"  // the RTL coverage build keeps the multiplier's counts
#include "specular/arith.h"
#include "specular/core.h"

namespace specular {
namespace {

constexpr int kNormBits = DefaultFormats::norm.width();  // 31: S10.20
constexpr int kOutBits = DefaultFormats::out.width();    // 32: S18.13
constexpr int kShift = DefaultFormats::norm.frac_bits - DefaultFormats::out.frac_bits;  // 7
static_assert(kNormBits == 31 && kOutBits == 32 && kShift == 7,
              "twin/multipliers.cmake verilates multiplier_rgb at these parameters");
constexpr code_t kNormMin = -(code_t{1} << (kNormBits - 1));
constexpr code_t kNormMax = (code_t{1} << (kNormBits - 1)) - 1;
constexpr __int128 kOutMax = (__int128{1} << (kOutBits - 1)) - 1;
constexpr __int128 kOutMin = -(__int128{1} << (kOutBits - 1));

/// The K·A codes multiplier 39 produces over the sweep grid under one policy pair, sorted, unique.
std::vector<code_t> sweep_norm_codes(Normalisation normalisation, Saturation saturation) {
  Config config;
  config.normalisation = normalisation;
  config.saturation = saturation;
  const Core core(config);
  const std::vector<code_t> cos_codes = tb::sweep_cos_codes(core.formats());
  std::vector<code_t> codes;
  codes.reserve(cos_codes.size() * n_max);
  for (code_t n = n_min; n <= static_cast<code_t>(n_max); ++n)
    for (const code_t cos : cos_codes) codes.push_back(core.run(Operands{cos, n, {0, 0, 0}}).norm39);
  std::sort(codes.begin(), codes.end());
  codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
  return codes;
}

/// K·A × I by definition: drop kShift bits rounding half up (floor of value + half),
/// then the S18.13 range, else its minimum or maximum code. Independent of arith.h.
code_t expected_product(code_t norm, code_t intensity) {
  const __int128 biased = static_cast<__int128>(norm) * intensity + (__int128{1} << (kShift - 1));
  __int128 rounded = biased / (__int128{1} << kShift);
  if (biased < 0 && rounded * (__int128{1} << kShift) != biased) --rounded;  // floor, not truncation
  return static_cast<code_t>(std::min(kOutMax, std::max(kOutMin, rounded)));
}

/// Codes within `radius` of `centre`, kept inside the S10.20 bus.
void add_around(std::vector<code_t>& codes, code_t centre, code_t radius) {
  for (code_t c = centre - radius; c <= centre + radius; ++c)
    if (c >= kNormMin && c <= kNormMax) codes.push_back(c);
}

TEST(RtlMultipliers, EverySweepKATimesEveryIntensityEqualsMulRgb) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<code_t> all;
  for (const Normalisation normalisation : {Normalisation::patent, Normalisation::energy, Normalisation::none})
    for (const Saturation saturation : {Saturation::clamp, Saturation::literal}) {
      const std::vector<code_t> codes = sweep_norm_codes(normalisation, saturation);
      ASSERT_FALSE(codes.empty());
      std::cout << "[ counts   ] " << to_string(normalisation) << "_" << to_string(saturation) << ": "
                << codes.size() << " distinct K*A codes, " << codes.front() << " .. " << codes.back()
                << " (S10.20)\n";
      all.insert(all.end(), codes.begin(), codes.end());
    }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  const double grid_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  VerilatedContext context;
  Vmultiplier_rgb mul(&context);
  const specular::RtlCoverageScope coverage(context);
  const std::uint32_t norm_mask = (std::uint32_t{1} << kNormBits) - 1;
  std::uint64_t products = 0, mismatches = 0, reference_mismatches = 0;
  std::string first_mismatch;
  const auto simulated = std::chrono::steady_clock::now();
  for (const code_t norm : all) {
    mul.norm = static_cast<std::uint32_t>(norm) & norm_mask;  // the 31-bit bus, two's complement
    for (code_t intensity = 0; intensity < 256; ++intensity) {
      mul.intensity = static_cast<std::uint8_t>(intensity);
      mul.eval();
      const code_t rtl = static_cast<std::int32_t>(mul.out);  // the 32-bit S18.13 bus, sign-extended
      const code_t model = arith::mul_rgb(DefaultFormats{}, norm, intensity);
      ++products;
      if (model != expected_product(norm, intensity)) ++reference_mismatches;
      if (rtl != model && mismatches++ == 0)
        first_mismatch = "K*A " + std::to_string(norm) + " x " + std::to_string(intensity) + ": rtl " +
                         std::to_string(rtl) + ", mul_rgb " + std::to_string(model);
    }
  }
  const double sim_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - simulated).count();
  std::cout << "[ counts   ] all six policies: " << all.size() << " distinct K*A codes x 256 intensities = "
            << products << " products, " << mismatches << " differences (rtl vs mul_rgb), "
            << reference_mismatches << " (mul_rgb vs the 128-bit definition)\n"
            << "[ rate     ] K*A grid " << grid_seconds << " s; products " << sim_seconds << " s, "
            << products / sim_seconds / 1e6 << " M products/s (eval + mul_rgb + reference)\n";
  EXPECT_EQ(products, all.size() * 256);
  EXPECT_EQ(mismatches, 0u) << "first: " << first_mismatch;
  EXPECT_EQ(reference_mismatches, 0u);
}

TEST(RtlMultipliers, CornersAndRandomCodesTimesEveryIntensityEqualMulRgb) {
  std::vector<code_t> codes;
  add_around(codes, 0, 4096);
  add_around(codes, kNormMin, 4096);
  add_around(codes, kNormMax, 4096);
  std::mt19937_64 engine(13);  // fixed seed: the same codes every run
  for (int i = 0; i < 16384; ++i)
    codes.push_back(kNormMin + static_cast<code_t>(engine() >> (64 - kNormBits)));
  std::sort(codes.begin(), codes.end());
  codes.erase(std::unique(codes.begin(), codes.end()), codes.end());

  VerilatedContext context;
  Vmultiplier_rgb mul(&context);
  const specular::RtlCoverageScope coverage(context);
  const std::uint32_t norm_mask = (std::uint32_t{1} << kNormBits) - 1;
  std::uint64_t products = 0, saturated = 0, mismatches = 0;
  std::string first_mismatch;
  for (const code_t norm : codes) {
    mul.norm = static_cast<std::uint32_t>(norm) & norm_mask;  // the 31-bit bus, two's complement
    for (code_t intensity = 0; intensity < 256; ++intensity) {
      mul.intensity = static_cast<std::uint8_t>(intensity);
      mul.eval();
      const code_t rtl = static_cast<std::int32_t>(mul.out);  // the 32-bit S18.13 bus, sign-extended
      const code_t expected = expected_product(norm, intensity);
      const code_t model = arith::mul_rgb(DefaultFormats{}, norm, intensity);
      ++products;
      saturated += expected == kOutMax || expected == kOutMin;
      if ((rtl != expected || model != expected) && mismatches++ == 0)
        first_mismatch = "K*A " + std::to_string(norm) + " x " + std::to_string(intensity) + ": rtl " +
                         std::to_string(rtl) + ", mul_rgb " + std::to_string(model) + ", expected " +
                         std::to_string(expected);
    }
  }
  std::cout << "[ counts   ] " << codes.size() << " K*A codes x 256 intensities = " << products
            << " products, " << saturated << " saturated, "
            << mismatches << " differences\n";
  EXPECT_EQ(mismatches, 0u) << "first: " << first_mismatch;
  // The format's ends are in the set: the largest products the bus can present.
  EXPECT_EQ(codes.front(), kNormMin);
  EXPECT_EQ(codes.back(), kNormMax);
  EXPECT_EQ(saturated, 0u);  // as the widths say (a saturation here would be a bug in expected_product)
}

}  // namespace
}  // namespace specular
