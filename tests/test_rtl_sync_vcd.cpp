// The synchronous variant's waveform (issue 19, must-have 3): `specular_tb --model
// rtl-sync --vcd` writes Verilator's VCD of its own nets. Parsed here: time unit 1 ps,
// the device's scope with pins 17–35 and Fig. 1's nets under the drawn twin's names, the
// sequencer's flip-flops, no parameters; every signal of waveforms/specular_rtl_sync.gtkw
// present. The waves are checked half period by half period against the variant's
// timing table (docs/rtl.md): start and the loads high from a quarter period before the
// start edge to a quarter period after it; pass 1, select 36, write 37 and 35 at every
// half period from each start edge to 3 T after it; register 9 holding the formula's
// pass-1 value 1 T after the start edge and A at 35↑ (2 T); pins 24–26 at 35↑ within
// the reference's tolerance.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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
using testing_support::parse_vcd;
using testing_support::scratch_subdir;
using testing_support::slurp;
using testing_support::Vcd;

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
const fs::path source_dir = SPECULAR_SOURCE_DIR;
const std::string dev = "TOP.specular_device_sync";
const std::string cus = "TOP.specular_device_sync.cus";
constexpr long long period_ps = 10000;  // specular_tb's default clock

/// specular_tb --model rtl-sync on waveforms/example.csv with a VCD; returns its path.
fs::path make_sync_vcd(const fs::path& dir) {
  const fs::path vcd = dir / "specular_rtl_sync.vcd";
  const std::string command = "cd '" + source_dir.string() + "' && '" + tb +
                              "' --model rtl-sync --input waveforms/example.csv --vcd '" +
                              vcd.string() + "' >'" + (dir / "out.txt").string() + "' 2>&1";
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

TEST(RtlSyncVcd, TimeUnitScopesAndNames) {
  const Vcd vcd = parse_vcd(slurp(make_sync_vcd(scratch_subdir("names"))));
  EXPECT_DOUBLE_EQ(vcd.timescale_seconds, 1e-12);
  EXPECT_TRUE(vcd.scopes.count(dev)) << "the device's scope";
  EXPECT_TRUE(vcd.scopes.count(cus)) << "the sequencer's scope";
  for (const char* pin : {"pin17_cos", "pin18_n", "pin19_h", "pin20_a", "pin21_r", "pin22_g",
                          "pin23_b", "pin24_r", "pin25_g", "pin26_b", "pin27_start", "pin28_clk",
                          "pin29_reset_n", "pin30_load_n", "pin31_load_r", "pin32_load_g",
                          "pin33_load_b", "pin34_carry", "pin35_done"})
    EXPECT_NE(vcd.find(dev + "." + pin), nullptr) << pin;
  const std::vector<std::pair<std::string, int>> buses = {
      {"reg1_q", 17},       {"reg2_q", 10},       {"mux3_address", 37}, {"rom5_log2", 28},
      {"mux4_operand", 18}, {"mul6_product", 37}, {"inv7_inverted", 37}, {"adder8_sum", 37},
      {"reg9_q", 37},       {"reg10_q", 8},       {"reg11_q", 8},       {"reg12_q", 8},
      {"rom38_k", 25},      {"mul39_norm", 31},   {"select36", 1},      {"write37", 1},
      {"load1", 1}};
  for (const auto& [name, width] : buses) {
    const Vcd::Var* v = vcd.find(dev + "." + name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_EQ(v->width, width) << name;
  }
  for (const char* net : {"pass1_q", "pass2_q", "done_q"})
    EXPECT_NE(vcd.find(cus + "." + net), nullptr) << net;
  for (const char* parameter : {"REG9_FRAC", "ROM5_IMAGE", "COS_FRAC"})
    EXPECT_EQ(vcd.find(dev + "." + parameter), nullptr) << parameter;
}

TEST(RtlSyncVcd, SaveFileSignalsAreAllInTheVcd) {
  const Vcd vcd = parse_vcd(slurp(make_sync_vcd(scratch_subdir("gtkw"))));
  std::ifstream save(source_dir / "waveforms" / "specular_rtl_sync.gtkw");
  ASSERT_TRUE(save) << "waveforms/specular_rtl_sync.gtkw";
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

// The variant's timing table (docs/rtl.md), start edge at t0 (a rising clock edge):
// the sequencer's outputs just after every half period.
struct Row {
  int half_periods;  ///< t0 + half_periods · T/2
  int pass1, select36, write37, done35;
};
const Row timing_table[] = {
    {0, 1, 0, 1, 1},  // t0: start sampled; register 1 ← pin 17; pass 1
    {1, 1, 0, 1, 1},  // T/2: nothing changes on a falling edge
    {2, 0, 1, 1, 0},  // T: register 9 ← pass 1; select 36 rises; 35 falls
    {3, 0, 1, 1, 0},
    {4, 0, 0, 0, 1},  // 2T: register 9 ← pass 2 (A); 35 rises: results valid
    {5, 0, 0, 0, 1},
};

TEST(RtlSyncVcd, TimingTableHalfPeriodByHalfPeriod) {
  const Vcd vcd = parse_vcd(slurp(make_sync_vcd(scratch_subdir("timing"))));
  const auto start_rises = vcd.rises(dev + ".pin27_start");
  const auto dones = vcd.rises(dev + ".pin35_done");
  ASSERT_EQ(start_rises.size(), examples.size());
  ASSERT_EQ(dones.size(), examples.size());
  const auto bit = [&](const std::string& name, long long t) { return vcd.at(name, t) == "1" ? 1 : 0; };
  std::vector<long long> starts;  // the start edges: a quarter period after start rises
  for (const long long r : start_rises) starts.push_back(r + period_ps / 4);
  const Formats f;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const long long t0 = starts[i];
    EXPECT_EQ(t0 % period_ps, 0) << "start " << i << " sampled at a rising clock edge";
    EXPECT_EQ(bit(dev + ".pin28_clk", t0), 1);
    EXPECT_EQ(bit(dev + ".pin27_start", t0), 1) << "start held over its edge";
    EXPECT_EQ(bit(dev + ".pin27_start", t0 + period_ps / 4), 0) << "start falls T/4 after its edge";
    EXPECT_EQ(dones[i] - t0, 2 * period_ps) << "start edge → 35↑ is 2 periods";
    for (const Row& row : timing_table) {
      const long long t = t0 + row.half_periods * period_ps / 2;
      Row expected{row.half_periods, 0, 0, 0, 1};
      for (const long long s : starts) {
        const long long h = (t - s) / (period_ps / 2);
        if (t < s || h > 5) continue;
        const Row& other = timing_table[h];
        expected.pass1 |= other.pass1;
        expected.select36 |= other.select36;
        expected.write37 |= other.write37;
        expected.done35 &= other.done35;
      }
      const std::string at = "start " + std::to_string(i) + " + " + std::to_string(row.half_periods) + " T/2";
      EXPECT_EQ(bit(cus + ".pass1_q", t), expected.pass1) << at;
      EXPECT_EQ(bit(dev + ".select36", t), expected.select36) << at;
      EXPECT_EQ(bit(dev + ".write37", t), expected.write37) << at;
      EXPECT_EQ(bit(dev + ".pin35_done", t), expected.done35) << at;
    }
    if (i + 1 < starts.size()) {
      EXPECT_GE(starts[i + 1] - t0, 2 * period_ps) << "starts at least 2 periods apart";
    }
    const Example& e = examples[i];
    const double cos_q = std::round(e.cos * 65536) / 65536;
    const double pass1 = 1 - e.n * std::log2(cos_q);
    const double a = std::max(0.0, 1 - 0.5 * std::log2(pass1));
    EXPECT_NEAR(f.reg9.to_real(code_at(vcd, dev + ".reg9_q", true, t0 + period_ps)), pass1,
                e.n * std::ldexp(1.0, -15))
        << "pass 1 of start " << i;
    EXPECT_NEAR(f.reg9.to_real(code_at(vcd, dev + ".reg9_q", true, dones[i])), a, std::ldexp(1.0, -10))
        << "A of start " << i;
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
