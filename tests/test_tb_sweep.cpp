// specular_tb --sweep on the pin model (issue 2 item 6): every n in 1..1000 × the
// dense cos grid, through the pins, one elaboration. The summary carries the count,
// max |norm − norm_ref| and where, max |norm − norm_exact| and where, and the verdict;
// its figures equal the core model's (the two agree bit for bit), and the formula's
// own worst error sits where the closed form puts it.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "testbench.h"

using namespace specular::tb;

namespace {

/// "max |norm - norm_ref|      = 4.1468e-05 at cos 0.9959259, n 1  (…)"
struct WorstLine {
  double value = -1, cos = -1;
  int n = -1;
  std::string text;
};

std::map<std::string, WorstLine> worst_lines(const std::string& summary) {
  std::map<std::string, WorstLine> lines;
  std::istringstream in(summary);
  std::string line;
  while (std::getline(in, line)) {
    const auto label_end = line.find(" = ");
    if (line.rfind("  max |", 0) != 0 || label_end == std::string::npos) continue;
    std::string label = line.substr(2, label_end - 2);
    label = label.substr(0, label.find_last_not_of(' ') + 1);
    WorstLine w;
    w.text = line;
    std::istringstream fields(line.substr(label_end + 3));
    std::string at, cos_word, n_word;
    fields >> w.value >> at >> cos_word >> w.cos;
    fields.ignore(2);  // ", "
    fields >> n_word >> w.n;
    lines[label] = w;
  }
  return lines;
}

}  // namespace

TEST(TbSweep, PinSweepSummaryMatchesTheCoreAndTheClosedForm) {
  std::ostringstream pin_out, pin_err, core_out, core_err;
  ASSERT_EQ(run_testbench({"--sweep"}, pin_out, pin_err), exit_pass) << pin_err.str();
  ASSERT_EQ(run_testbench({"--sweep", "--model", "core"}, core_out, core_err), exit_pass)
      << core_err.str();
  const std::string pin = pin_out.str(), core = core_out.str();

  // 1021 cos values × 1000 n: the 513 multiples of 2^-9 in [0, 1] and the 512 codes
  // 1 − k·2^-16 (k = 1..512), of which 4 (k = 128, 256, 384, 512) are already counted.
  EXPECT_NE(pin.find("summary: 1021000 computation(s), 0 out of tolerance: PASS"), std::string::npos) << pin;
  EXPECT_NE(pin.find("cycles, start to pin 35 rising: 2.5 (measured on the pins)"), std::string::npos) << pin;

  const auto pin_lines = worst_lines(pin), core_lines = worst_lines(core);
  for (const char* label : {"max |approx - approx_ref|", "max |norm - norm_ref|",
                            "max |norm - norm_exact|", "max |out - out_ref|"}) {
    SCOPED_TRACE(label);
    ASSERT_TRUE(pin_lines.count(label)) << pin;
    ASSERT_TRUE(core_lines.count(label)) << core;
    const WorstLine& p = pin_lines.at(label);
    EXPECT_EQ(p.text, core_lines.at(label).text) << "pin and core agree bit for bit";
    EXPECT_GE(p.value, 0.0);
    EXPECT_GE(p.cos, 0.0);
    EXPECT_LE(p.cos, 1.0);
    EXPECT_GE(p.n, 1);
    EXPECT_LE(p.n, 1000);
  }
  // The bounds of issue 2 item 7 (patent policy: K = 2π/(n+2) ≤ 2π/3, so max(1, K)
  // ≤ 2.1): every worst case inside them.
  EXPECT_LE(pin_lines.at("max |approx - approx_ref|").value, std::ldexp(1.0, -10));
  EXPECT_LE(pin_lines.at("max |norm - norm_ref|").value, std::ldexp(1.0, -10) * 2 * M_PI / 3);
  // The formula's own worst error, from the spec: clamped A is 0 at x = n·log2 cos λ
  // = −3 where cos^n λ = 1/8; largest with K(1) = 2π/3, i.e. at n = 1, cos λ = 0.125
  // (a grid point, 64·2^-9): 0.125·2π/3.
  const WorstLine& exact = pin_lines.at("max |norm - norm_exact|");
  EXPECT_NEAR(exact.value, 0.125 * 2 * M_PI / 3, 1e-4);
  EXPECT_EQ(exact.n, 1);
  EXPECT_DOUBLE_EQ(exact.cos, 0.125);
}
