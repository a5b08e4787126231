// Operand classes that no other quick test drives through the register map (issue 37,
// functional coverage's cos/ and reg9/ bins): COS codes with their leading one at bits
// 2, 3, 4, 5 and 10 (ROM 5 segments), and register 9 after pass 2 read back negative
// (literal saturation), clamped to 0 and positive. Each case writes COS, N, R, G, B and
// START to an `lt` target through the TLM bench (which records the classes), reads
// OUT_R/G/B and REG9_PASS2_LO/HI, and checks them against the double reference
// (reference.h, the project's tolerances), register 9's sign against the spec's rule
// (A = 1 - 1/2 log2(1 - x), x = n log2 cos: negative for x < -3, device.md section 1),
// computed here, not read from the model.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "specular/reference.h"
#include "support/tlm_bench.h"

namespace {

using namespace specular;
using namespace specular::tlm_testing;

struct Case {
  const char* name;
  Saturation saturation;
  std::uint32_t cos;  ///< U1.16 code
  std::uint32_t n;
  std::array<std::uint32_t, 3> rgb;
};

const Case cases[] = {
    {"cos_bit2_literal", Saturation::literal, 5, 1, {255, 128, 1}},
    {"cos_bit3_literal", Saturation::literal, 12, 2, {255, 0, 77}},
    {"cos_bit4_literal", Saturation::literal, 17, 3, {200, 255, 1}},
    {"cos_bit5_literal", Saturation::literal, 40, 1, {1, 255, 90}},
    {"cos_bit10_literal", Saturation::literal, 1500, 1, {255, 255, 255}},
    {"reg9_negative_literal", Saturation::literal, 4096, 1, {255, 100, 10}},   // x = -4
    {"reg9_clamped_zero", Saturation::clamp, 4096, 1, {255, 100, 10}},         // x = -4
    {"reg9_positive_clamp", Saturation::clamp, 60000, 8, {255, 100, 10}},      // x = -1.02
    {"reg9_positive_literal", Saturation::literal, 65536, 1000, {9, 99, 255}},  // x = 0: A = 1
};

// ctest's test names carry the parameter as gtest prints it: the case's name, not its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class OperandClasses : public ::testing::TestWithParam<Case> {};

TEST_P(OperandClasses, ResultsAndRegister9MatchTheReference) {
  const Case c = GetParam();
  Config config;
  config.saturation = c.saturation;
  const Formats formats(config.widths);
  // the spec's sign of A, from x = n log2 cos (x > -3: positive; below: negative, or 0 clamped)
  const double x = c.n * std::log2(c.cos / 65536.0);
  ASSERT_GT(std::fabs(x + 3), 0.1) << "a case too near A's zero to tell its sign";
  const int sign = x > -3 ? 1 : c.saturation == Saturation::literal ? -1 : 0;
  std::int64_t reg9 = 0;
  std::array<std::int32_t, 3> out{};
  run(
      {Kind::lt},
      [&](TlmBench& bench) {
        Endpoint& e = bench.at(0);
        EXPECT_EQ(e.write(Reg::cos, c.cos), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(e.write(Reg::n, c.n), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(e.write(Reg::r, c.rgb[0]), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(e.write(Reg::g, c.rgb[1]), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(e.write(Reg::b, c.rgb[2]), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(e.write(Reg::control, control_bits::start), tlm::TLM_OK_RESPONSE);
        for (int ch = 0; ch < 3; ++ch)
          out[ch] = static_cast<std::int32_t>(e.read(static_cast<Reg>(static_cast<int>(Reg::out_r) + ch)));
        const std::uint64_t lo = e.read(Reg::reg9_pass2_lo), hi = e.read(Reg::reg9_pass2_hi);
        reg9 = static_cast<std::int64_t>(hi << 32 | lo);
      },
      config);
  const double cos_q = formats.cos.to_real(c.cos);
  const double a = formats.reg9.to_real(reg9);
  EXPECT_NEAR(a, reference::approx(cos_q, c.n, c.saturation, config.widths.cos_frac_bits),
              reference::approx_tolerance());
  EXPECT_EQ((reg9 > 0) - (reg9 < 0), sign) << "register 9's sign; A = " << a;
  const std::array<double, 3> rgb{double(c.rgb[0]), double(c.rgb[1]), double(c.rgb[2])};
  const reference::Figures ref =
      reference::evaluate(cos_q, c.n, rgb, config.normalisation, config.saturation, config.widths.cos_frac_bits);
  const double k = reference::k(c.n, config.normalisation);
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(formats.out.to_real(out[ch]), ref.out_ref[ch],
                reference::out_tolerance(k, rgb[ch], formats.out.lsb()))
        << "channel " << ch;
}

INSTANTIATE_TEST_SUITE_P(Cases, OperandClasses, ::testing::ValuesIn(cases),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
