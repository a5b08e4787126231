// The RTL twin's waveform (issue 13, must-have 4): `specular_tb --model rtl --vcd`
// writes Verilator's VCD of the RTL's own nets. Parsed here: time unit 1 ps, the
// device's scope with pins 17–35 and every net of Fig. 1 under the SystemC model's
// names, control unit 16's flip-flops and gates, no parameters; every signal of
// waveforms/specular_rtl.gtkw present, so the saved view opens ready to read. The
// waves are checked half period by half period against the spec's timing table
// (§3): Q41, Q42, select 36 (Q43), write 37 and 35 at every half period from each
// start to 3 T after it, register 9 holding the formula's pass-1 value and A after
// the two writes, and pins 24–26 at 35↑ within the reference's tolerance.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "specular/format.h"
#include "specular/reference.h"
#include "support/scratch.h"
#include "support/subprocess.h"
#include "support/vcd.h"

namespace fs = std::filesystem;

namespace specular {
namespace {

using testing_support::code_at;
using testing_support::slurp;
using testing_support::parse_vcd;
using testing_support::Vcd;
using testing_support::scratch_subdir;

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
const fs::path source_dir = SPECULAR_SOURCE_DIR;
const std::string dev = "TOP.specular_device";
const std::string cu16 = "TOP.specular_device.cu16";
constexpr long long period_ps = 10000;  // specular_tb's default clock

/// specular_tb --model rtl on waveforms/example.csv with a VCD; returns the VCD's path.
fs::path make_rtl_vcd(const fs::path& dir) {
  const fs::path vcd = dir / "specular_rtl.vcd";
  const std::string command = "cd '" + source_dir.string() + "' && '" + tb +
                              "' --model rtl --input waveforms/example.csv --vcd '" + vcd.string() +
                              "' >'" + (dir / "out.txt").string() + "' 2>&1";
  const int raw = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << slurp(dir / "out.txt");
  return vcd;
}

/// waveforms/example.csv, written out again: cos, n, R, G, B.
struct Example {
  double cos;
  int n;
  int rgb[3];
};
const std::vector<Example> examples = {{0.9, 10, {200, 100, 50}},
                                       {0.95, 10, {200, 100, 50}},
                                       {1, 10, {200, 100, 50}},
                                       {0.99, 100, {255, 128, 0}}};

TEST(RtlVcd, TimeUnitScopesAndPatentNames) {
  const fs::path vcd_path = make_rtl_vcd(scratch_subdir("names"));
  const std::string text = slurp(vcd_path);
  const Vcd vcd = parse_vcd(text);
  EXPECT_DOUBLE_EQ(vcd.timescale_seconds, 1e-12);
  EXPECT_TRUE(vcd.scopes.count(dev)) << "the device's scope";
  EXPECT_TRUE(vcd.scopes.count(cu16)) << "control unit 16's scope";
  for (const char* pin : {"pin17_cos", "pin18_n", "pin19_h", "pin20_a", "pin21_r", "pin22_g",
                          "pin23_b", "pin24_r", "pin25_g", "pin26_b", "pin27_start", "pin28_clk",
                          "pin29_reset_n", "pin30_load_n", "pin31_load_r", "pin32_load_g",
                          "pin33_load_b", "pin34_carry", "pin35_done"})
    EXPECT_NE(vcd.find(dev + "." + pin), nullptr) << pin;
  // Fig. 1: every block's output net, at its bus width, as in the SystemC model.
  const std::vector<std::pair<std::string, int>> buses = {
      {"reg1_q", 17},       {"reg2_q", 10},       {"mux3_address", 37}, {"rom5_log2", 28},
      {"mux4_operand", 18}, {"mul6_product", 37}, {"inv7_inverted", 37}, {"adder8_sum", 37},
      {"reg9_q", 37},       {"reg10_q", 8},       {"reg11_q", 8},       {"reg12_q", 8},
      {"rom38_k", 25},      {"mul39_norm", 31},   {"select36", 1},      {"write37", 1}};
  for (const auto& [name, width] : buses) {
    const Vcd::Var* v = vcd.find(dev + "." + name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_EQ(v->width, width) << name;
  }
  // Fig. 2: the flip-flops and gates of control unit 16.
  for (const char* net : {"q41", "q42", "inv44_y", "and40_y", "nand45_y"})
    EXPECT_NE(vcd.find(cu16 + "." + net), nullptr) << net;
  // Nets only: the widths and file names the RTL was built with are not waveforms.
  for (const char* parameter : {"REG9_FRAC", "ROM5_IMAGE", "COS_FRAC"})
    EXPECT_EQ(vcd.find(dev + "." + parameter), nullptr) << parameter;
}

TEST(RtlVcd, SaveFileSignalsAreAllInTheVcd) {
  const Vcd vcd = parse_vcd(slurp(make_rtl_vcd(scratch_subdir("gtkw"))));
  std::ifstream save(source_dir / "waveforms" / "specular_rtl.gtkw");
  ASSERT_TRUE(save) << "waveforms/specular_rtl.gtkw";
  int signals = 0;
  for (std::string line; std::getline(save, line);) {
    if (line.rfind("TOP.", 0) != 0) continue;
    ++signals;
    bool found = false;
    for (const auto& v : vcd.vars) found = found || v.gtkwave() == line;
    EXPECT_TRUE(found) << line << " is in the save file but not in the VCD";
  }
  EXPECT_GE(signals, 20);
}

// Spec §3's table, with a start at t0 on a rising clock edge and period T: the
// state of the control unit's outputs just after every half period.
struct Row {
  int half_periods;  ///< t0 + half_periods · T/2
  int q41, q42, select36, write37, done35;
};
const Row timing_table[] = {
    {0, 1, 0, 0, 0, 1},  // start: Q41 ← 1
    {1, 1, 1, 0, 0, 1},  // T/2, clk falls: Q42 ← 1
    {2, 0, 1, 0, 1, 1},  // T, clk rises: NAND 45 low → 37 rises (pass 1); AND 40 clears Q41
    {3, 0, 0, 1, 0, 1},  // 3T/2, clk falls: Q43 ← 1 (select 36), Q42 ← 0
    {4, 0, 0, 1, 1, 0},  // 2T, clk rises: NAND 46 low → 35 falls, 37 rises (pass 2)
    {5, 0, 0, 0, 0, 1},  // 5T/2, clk falls: Q43 ← 0, 35 rises: results valid
};

TEST(RtlVcd, TimingTableHalfPeriodByHalfPeriod) {
  const Vcd vcd = parse_vcd(slurp(make_rtl_vcd(scratch_subdir("timing"))));
  const auto starts = vcd.rises(dev + ".pin27_start");
  const auto dones = vcd.rises(dev + ".pin35_done");
  ASSERT_EQ(starts.size(), examples.size());
  ASSERT_EQ(dones.size(), examples.size());
  const auto bit = [&](const std::string& name, long long t) { return vcd.at(name, t) == "1" ? 1 : 0; };
  const Formats f;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const long long t0 = starts[i];
    EXPECT_EQ(t0 % period_ps, 0) << "start " << i << " on a rising clock edge";
    EXPECT_EQ(bit(dev + ".pin28_clk", t0), 1);
    EXPECT_EQ(dones[i] - t0, 5 * period_ps / 2) << "start → 35↑ is 2.5 periods";
    // Starts 2 T apart (the streaming protocol) overlap: at each instant the rows of
    // every operation in flight combine (Q41, Q42, select 36 and write 37 high when one
    // has them high, 35 low when one has it low).
    for (const Row& row : timing_table) {
      const long long t = t0 + row.half_periods * period_ps / 2;
      Row expected{row.half_periods, 0, 0, 0, 0, 1};
      for (const long long s : starts) {
        const long long h = (t - s) / (period_ps / 2);
        if (t < s || h > 5) continue;
        const Row& other = timing_table[h];
        expected.q41 |= other.q41;
        expected.q42 |= other.q42;
        expected.select36 |= other.select36;
        expected.write37 |= other.write37;
        expected.done35 &= other.done35;
      }
      const std::string at = "start " + std::to_string(i) + " + " + std::to_string(row.half_periods) + " T/2";
      EXPECT_EQ(bit(cu16 + ".q41", t), expected.q41) << at;
      EXPECT_EQ(bit(cu16 + ".q42", t), expected.q42) << at;
      EXPECT_EQ(bit(dev + ".select36", t), expected.select36) << at;
      EXPECT_EQ(bit(dev + ".write37", t), expected.write37) << at;
      EXPECT_EQ(bit(dev + ".pin35_done", t), expected.done35) << at;
    }
    if (i + 1 < starts.size()) {
      EXPECT_GE(starts[i + 1] - t0, 2 * period_ps) << "starts at least 2 periods apart";
    }
    // Register 9 after each write, against the formula on register 1's quantised cos.
    const Example& e = examples[i];
    const double cos_q = std::round(e.cos * 65536) / 65536;
    const double pass1 = 1 - e.n * std::log2(cos_q);
    const double a = std::max(0.0, 1 - 0.5 * std::log2(pass1));
    EXPECT_NEAR(f.reg9.to_real(code_at(vcd, dev + ".reg9_q", true, t0 + period_ps)), pass1,
                e.n * std::ldexp(1.0, -15))
        << "pass 1 of start " << i;
    EXPECT_NEAR(f.reg9.to_real(code_at(vcd, dev + ".reg9_q", true, dones[i])), a, std::ldexp(1.0, -10))
        << "A of start " << i;
    // Pins 24–26 at 35↑ against the double reference (patent policy: K = 2π/(n+2)).
    const std::array<double, 3> intensity{double(e.rgb[0]), double(e.rgb[1]), double(e.rgb[2])};
    const reference::Figures ref = reference::evaluate(cos_q, e.n, intensity, Normalisation::patent,
                                                       Saturation::clamp, 16);
    const double k = 2 * M_PI / (e.n + 2);
    const char* pins[] = {".pin24_r", ".pin25_g", ".pin26_b"};
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(f.out.to_real(code_at(vcd, dev + pins[ch], true, dones[i])), ref.out_ref[ch],
                  reference::out_tolerance(k, intensity[ch], f.out.lsb()))
          << "start " << i << " channel " << ch;
  }
}

}  // namespace
}  // namespace specular
