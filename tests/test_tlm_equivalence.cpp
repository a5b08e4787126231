// The two implementations behind the TLM socket — `lt` (the core, annotated) and `pin`
// (a transactor on the netlist) — return the same bits, and both stay within the
// double reference's tolerances (reference.h): on a sampled sweep through the batch
// window and on random single operations through the registers, under each policy.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "specular/reference.h"
#include "support/accuracy_sweep.h"
#include "support/tlm_bench.h"

namespace specular {
namespace {

using namespace tlm_testing;

/// Pins 24–26 (two's complement codes) against the double reference.
void expect_outputs_near_reference(const Config& config, code_t cos, unsigned n,
                                   const std::array<code_t, 3>& rgb, const std::int32_t* out) {
  const Formats f(config.widths);
  const std::array<double, 3> intensity{double(rgb[0]), double(rgb[1]), double(rgb[2])};
  const reference::Figures ref =
      reference::evaluate(f.cos.to_real(cos), n, intensity, config.normalisation,
                          config.saturation, config.widths.cos_frac_bits);
  const double k = reference::k(n, config.normalisation);
  for (int ch = 0; ch < 3; ++ch)
    ASSERT_NEAR(f.out.to_real(out[ch]), ref.out_ref[ch],
                reference::out_tolerance(k, intensity[ch], f.out.lsb()))
        << "cos code " << cos << ", n " << n << ", channel " << ch;
}

// Every 9th n from 1 to 1000 (1000 included) × cos in steps of 2^-6 plus 0, the
// smallest codes and the last codes below 1.0, through BATCH_COS / BATCH_OUT.
TEST(TlmEquivalence, SampledSweepThroughTheBatchWindow) {
  const Config config;
  long compared = 0;
  run({Kind::lt, Kind::pin}, [&](TlmBench& b) {
    const Formats f(config.widths);
    std::vector<std::uint32_t> cos;
    for (const code_t c : testing_support::cos_codes(f, 1024)) cos.push_back(static_cast<std::uint32_t>(c));
    ASSERT_EQ(cos.size(), 76u) << "65 multiples of 1024, codes 1..3, 65528..65535";
    ASSERT_EQ(cos.front(), 0u);
    ASSERT_EQ(cos.back(), 65536u);
    std::vector<std::int32_t> lt(3 * cos.size()), pin(3 * cos.size());
    for (unsigned n = 1; n <= 1000; n += 9) {
      const std::array<code_t, 3> rgb{255, 128 + n % 128, n % 256};
      b[Kind::lt].driver.compute_batch(n, rgb, cos.data(), cos.size(), lt.data());
      b[Kind::pin].driver.compute_batch(n, rgb, cos.data(), cos.size(), pin.data());
      for (std::size_t i = 0; i < cos.size(); ++i) {
        for (int ch = 0; ch < 3; ++ch)
          ASSERT_EQ(lt[3 * i + ch], pin[3 * i + ch])
              << "cos code " << cos[i] << ", n " << n << ", channel " << ch;
        expect_outputs_near_reference(config, cos[i], n, rgb, &lt[3 * i]);
        ++compared;
      }
    }
  });
  EXPECT_EQ(compared, 112 * 76) << "112 values of n × 76 cos codes";
}

// Random single operations through the registers (COS, N, R, G, B, START), every
// inspection register included, under each configuration.
class TlmEquivalenceRandom : public testing::TestWithParam<Config> {};

TEST_P(TlmEquivalenceRandom, SingleOperationsAgreeInEveryRegister) {
  const Config config = GetParam();
  constexpr int operations = 1500;
  int compared = 0;
  run(
      {Kind::lt, Kind::pin},
      [&](TlmBench& b) {
        const Formats f(config.widths);
        std::mt19937_64 random(20240531);
        std::uniform_int_distribution<code_t> cos(0, 65536), n(1, 1000), rgb(0, 255);
        Operands op;
        for (int i = 0; i < operations; ++i) {
          op.cos = i % 10 == 0 ? 65536 - i / 10 % 4 : cos(random);  // the last codes too
          if (i % 7 != 0) op.n = n(random);  // else n and R, G, B stay: no operand writes
          if (i % 7 != 0) op.rgb = {rgb(random), rgb(random), rgb(random)};
          const Result lt = b[Kind::lt].driver.compute_inspected(op);
          const Result pin = b[Kind::pin].driver.compute_inspected(op);
          ASSERT_EQ(lt.reg1, op.cos);
          ASSERT_EQ(pin.reg1, op.cos);
          ASSERT_EQ(lt.reg9_pass1, pin.reg9_pass1) << i;
          ASSERT_EQ(lt.reg9_pass2, pin.reg9_pass2) << i;
          ASSERT_EQ(lt.rom38_k, pin.rom38_k) << i;
          ASSERT_EQ(lt.norm39, pin.norm39) << i;
          ASSERT_EQ(lt.out, pin.out) << i;

          const unsigned nn = static_cast<unsigned>(op.n);
          const std::array<double, 3> intensity{double(op.rgb[0]), double(op.rgb[1]),
                                                double(op.rgb[2])};
          const reference::Figures ref =
              reference::evaluate(f.cos.to_real(op.cos), nn, intensity, config.normalisation,
                                  config.saturation, config.widths.cos_frac_bits);
          const double k = reference::k(nn, config.normalisation);
          ASSERT_NEAR(f.reg9.to_real(lt.reg9_pass2), ref.approx_ref, reference::approx_tolerance());
          ASSERT_NEAR(f.norm.to_real(lt.norm39), ref.norm_ref, reference::norm_tolerance(k));
          const std::int32_t out[3] = {static_cast<std::int32_t>(lt.out[0]),
                                       static_cast<std::int32_t>(lt.out[1]),
                                       static_cast<std::int32_t>(lt.out[2])};
          expect_outputs_near_reference(config, op.cos, nn, op.rgb, out);
          ++compared;
        }
      },
      config);
  EXPECT_EQ(compared, operations);
}

Config make_config(Normalisation normalisation, Saturation saturation) {
  Config c;
  c.normalisation = normalisation;
  c.saturation = saturation;
  return c;
}

std::string config_name(const testing::TestParamInfo<Config>& info) {
  const char* names[] = {"patent", "energy", "none"};
  return std::string(names[static_cast<int>(info.param.normalisation)]) +
         (info.param.saturation == Saturation::clamp ? "_clamp" : "_literal");
}

INSTANTIATE_TEST_SUITE_P(Policies, TlmEquivalenceRandom,
                         testing::Values(make_config(Normalisation::patent, Saturation::clamp),
                                         make_config(Normalisation::energy, Saturation::literal),
                                         make_config(Normalisation::none, Saturation::clamp)),
                         config_name);

}  // namespace
}  // namespace specular
