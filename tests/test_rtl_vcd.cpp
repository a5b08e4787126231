// The RTL twins' waveforms (issue 13 must-have 4, issue 19 must-have 3): `specular_tb
// --model rtl --vcd` and `--model rtl-sync --vcd` write Verilator's VCD of the RTL's own
// nets. Parsed here, for each twin: time unit 1 ps, the device's scope with pins 17–35
// and every net of Fig. 1 under the SystemC model's names, the control unit's
// flip-flops and gates (control unit 16 of Fig. 2; the variant's sequencer), no
// parameters; every signal of its saved GTKWave view present, so the view opens ready
// to read. The waves are checked half period by half period against each timing table
// — the spec's (§3): Q41, Q42, select 36 (Q43), write 37 and 35 from each start to 3 T
// after it; the variant's (docs/rtl.md): start and the loads held from a quarter period
// before the start edge to a quarter period after it, pass 1, select 36, write 37 and 35
// — with register 9 holding the formula's pass-1 value 1 T after the start (edge) and A
// at 35↑, and pins 24–26 at 35↑ within the reference's tolerance.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "specular/format.h"
#include "specular/reference.h"
#include "support/example_csv.h"
#include "support/scratch.h"
#include "support/subprocess.h"
#include "support/vcd.h"

namespace fs = std::filesystem;

namespace specular {
namespace {

using testing_support::code_at;
using testing_support::Example;
using testing_support::examples;
using testing_support::parse_vcd;
using testing_support::scratch_subdir;
using testing_support::slurp;
using testing_support::Vcd;

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
const fs::path source_dir = SPECULAR_SOURCE_DIR;
constexpr long long period_ps = 10000;  // specular_tb's default clock

/// What differs between the two twins' traces.
struct TwinTrace {
  std::string model;                ///< specular_tb --model
  std::string device;               ///< the device's scope
  std::string control;              ///< the control unit's scope
  std::vector<std::string> control_nets;
  std::vector<std::pair<std::string, int>> own_buses;  ///< nets only this twin has, and widths
  std::string save_file;            ///< its GTKWave view in waveforms/
};
const TwinTrace drawn{"rtl", "TOP.specular_device", "TOP.specular_device.cu16",
                      {"q41", "q42", "inv44_y", "and40_y", "nand45_y"}, {}, "specular_rtl.gtkw"};
const TwinTrace sync{"rtl-sync", "TOP.specular_device_sync", "TOP.specular_device_sync.cus",
                     {"pass1_q", "pass2_q", "done_q"}, {{"load1", 1}}, "specular_rtl_sync.gtkw"};

/// specular_tb --model <twin> on waveforms/example.csv with a VCD, parsed.
Vcd make_vcd(const TwinTrace& twin, const fs::path& dir) {
  const fs::path vcd = dir / "trace.vcd";
  const std::string command = "cd '" + source_dir.string() + "' && '" + tb + "' --model " +
                              twin.model + " --input waveforms/example.csv --vcd '" + vcd.string() +
                              "' >'" + (dir / "out.txt").string() + "' 2>&1";
  const int raw = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << slurp(dir / "out.txt");
  return parse_vcd(slurp(vcd));
}

void expect_scopes_and_patent_names(const TwinTrace& twin) {
  const Vcd vcd = make_vcd(twin, scratch_subdir("names"));
  const std::string& dev = twin.device;
  EXPECT_DOUBLE_EQ(vcd.timescale_seconds, 1e-12);
  EXPECT_TRUE(vcd.scopes.count(dev)) << "the device's scope";
  EXPECT_TRUE(vcd.scopes.count(twin.control)) << "the control unit's scope";
  for (const char* pin : {"pin17_cos", "pin18_n", "pin19_h", "pin20_a", "pin21_r", "pin22_g",
                          "pin23_b", "pin24_r", "pin25_g", "pin26_b", "pin27_start", "pin28_clk",
                          "pin29_reset_n", "pin30_load_n", "pin31_load_r", "pin32_load_g",
                          "pin33_load_b", "pin34_carry", "pin35_done"})
    EXPECT_NE(vcd.find(dev + "." + pin), nullptr) << pin;
  // Fig. 1: every block's output net, at its bus width, as in the SystemC model.
  std::vector<std::pair<std::string, int>> buses = {
      {"reg1_q", 17},       {"reg2_q", 10},       {"mux3_address", 37}, {"rom5_log2", 28},
      {"mux4_operand", 18}, {"mul6_product", 37}, {"inv7_inverted", 37}, {"adder8_sum", 37},
      {"reg9_q", 37},       {"reg10_q", 8},       {"reg11_q", 8},       {"reg12_q", 8},
      {"rom38_k", 25},      {"mul39_norm", 31},   {"select36", 1},      {"write37", 1}};
  buses.insert(buses.end(), twin.own_buses.begin(), twin.own_buses.end());
  for (const auto& [name, width] : buses) {
    const Vcd::Var* v = vcd.find(dev + "." + name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_EQ(v->width, width) << name;
  }
  for (const std::string& net : twin.control_nets)
    EXPECT_NE(vcd.find(twin.control + "." + net), nullptr) << net;
  // Nets only: the widths and file names the RTL was built with are not waveforms.
  for (const char* parameter : {"REG9_FRAC", "ROM5_IMAGE", "COS_FRAC"})
    EXPECT_EQ(vcd.find(dev + "." + parameter), nullptr) << parameter;
}

void expect_save_file_signals_in_the_vcd(const TwinTrace& twin) {
  const Vcd vcd = make_vcd(twin, scratch_subdir("gtkw"));
  std::ifstream save(source_dir / "waveforms" / twin.save_file);
  ASSERT_TRUE(save) << "waveforms/" << twin.save_file;
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

/// A timing table from a start (edge) at t0: row h holds the listed nets just after
/// t0 + h·T/2, h = 0..5. Starts 2 T apart (the streaming protocol) overlap: a net shows
/// its active value when any operation in flight has it (35 is active low).
struct TimingTable {
  std::vector<std::string> nets;       ///< below the device's scope
  std::vector<int> idle;               ///< each net with no operation in flight
  std::vector<std::vector<int>> rows;  ///< rows[h][net]
};

void expect_timing_table(const Vcd& vcd, const std::string& dev, const TimingTable& table,
                         const std::vector<long long>& starts) {
  const auto bit = [&](const std::string& name, long long t) { return vcd.at(name, t) == "1" ? 1 : 0; };
  const long long half = period_ps / 2;
  for (std::size_t i = 0; i < starts.size(); ++i)
    for (std::size_t h = 0; h < table.rows.size(); ++h) {
      const long long t = starts[i] + static_cast<long long>(h) * half;
      for (std::size_t net = 0; net < table.nets.size(); ++net) {
        int expected = table.idle[net];
        for (const long long s : starts) {
          if (t < s || (t - s) / half >= static_cast<long long>(table.rows.size())) continue;
          const int value = table.rows[static_cast<std::size_t>((t - s) / half)][net];
          if (value != table.idle[net]) expected = value;
        }
        EXPECT_EQ(bit(dev + "." + table.nets[net], t), expected)
            << table.nets[net] << " at start " << i << " + " << h << " T/2";
      }
    }
}


/// Register 9 1 T after start (edge) `t0` and at 35↑ (`done`) against the formula on
/// register 1's quantised cos; pins 24–26 at 35↑ against the double reference (patent
/// policy: K = 2π/(n+2)).
void expect_register9_and_outputs(const Vcd& vcd, const std::string& dev, std::size_t i,
                                  long long t0, long long done) {
  const Formats f;
  const Example& e = examples[i];
  const double cos_q = std::round(e.cos * 65536) / 65536;
  const double pass1 = 1 - e.n * std::log2(cos_q);
  const double a = std::max(0.0, 1 - 0.5 * std::log2(pass1));
  EXPECT_NEAR(f.reg9.to_real(code_at(vcd, dev + ".reg9_q", true, t0 + period_ps)), pass1,
              e.n * std::ldexp(1.0, -15))
      << "pass 1 of start " << i;
  EXPECT_NEAR(f.reg9.to_real(code_at(vcd, dev + ".reg9_q", true, done)), a, std::ldexp(1.0, -10))
      << "A of start " << i;
  const std::array<double, 3> intensity{double(e.rgb[0]), double(e.rgb[1]), double(e.rgb[2])};
  const reference::Figures ref = reference::evaluate(cos_q, e.n, intensity, Normalisation::patent,
                                                     Saturation::clamp, 16);
  const double k = 2 * M_PI / (e.n + 2);
  const char* pins[] = {".pin24_r", ".pin25_g", ".pin26_b"};
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(f.out.to_real(code_at(vcd, dev + pins[ch], true, done)), ref.out_ref[ch],
                reference::out_tolerance(k, intensity[ch], f.out.lsb()))
        << "start " << i << " channel " << ch;
}

/// What both twins' traces show per start (edge) and its 35↑: the start on a rising
/// clock edge, 35 rising `done_ps` after it, starts at least 2 periods apart, and
/// register 9 and pins 24–26 as expect_register9_and_outputs() says.
void expect_starts_and_results(const Vcd& vcd, const std::string& dev,
                               const std::vector<long long>& starts,
                               const std::vector<long long>& dones, long long done_ps) {
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const long long t0 = starts[i];
    EXPECT_EQ(t0 % period_ps, 0) << "start " << i << " on a rising clock edge";
    EXPECT_EQ(vcd.at(dev + ".pin28_clk", t0), "1");
    EXPECT_EQ(dones[i] - t0, done_ps) << "start " << i << " → 35↑";
    if (i + 1 < starts.size()) {
      EXPECT_GE(starts[i + 1] - t0, 2 * period_ps) << "starts at least 2 periods apart";
    }
    expect_register9_and_outputs(vcd, dev, i, t0, dones[i]);
  }
}

// ---- the drawn device: spec §3's table, start on a rising clock edge ----------------

const TimingTable spec_table{
    {"cu16.q41", "cu16.q42", "select36", "write37", "pin35_done"},
    {0, 0, 0, 0, 1},
    {
        {1, 0, 0, 0, 1},  // start: Q41 ← 1
        {1, 1, 0, 0, 1},  // T/2, clk falls: Q42 ← 1
        {0, 1, 0, 1, 1},  // T, clk rises: NAND 45 low → 37 rises (pass 1); AND 40 clears Q41
        {0, 0, 1, 0, 1},  // 3T/2, clk falls: Q43 ← 1 (select 36), Q42 ← 0
        {0, 0, 1, 1, 0},  // 2T, clk rises: NAND 46 low → 35 falls, 37 rises (pass 2)
        {0, 0, 0, 0, 1},  // 5T/2, clk falls: Q43 ← 0, 35 rises: results valid
    }};

TEST(RtlVcd, TimeUnitScopesAndPatentNames) { expect_scopes_and_patent_names(drawn); }
TEST(RtlVcd, SaveFileSignalsAreAllInTheVcd) { expect_save_file_signals_in_the_vcd(drawn); }

TEST(RtlVcd, TimingTableHalfPeriodByHalfPeriod) {
  const Vcd vcd = make_vcd(drawn, scratch_subdir("timing"));
  const std::string& dev = drawn.device;
  const auto starts = vcd.rises(dev + ".pin27_start");
  const auto dones = vcd.rises(dev + ".pin35_done");
  ASSERT_EQ(starts.size(), examples.size());
  ASSERT_EQ(dones.size(), examples.size());
  expect_starts_and_results(vcd, dev, starts, dones, 5 * period_ps / 2);  // 2.5 periods
  expect_timing_table(vcd, dev, spec_table, starts);
}

// ---- the synchronous variant: docs/rtl.md's table, from the start edge --------------

const TimingTable sync_table{
    {"cus.pass1_q", "select36", "write37", "pin35_done"},
    {0, 0, 0, 1},
    {
        {1, 0, 1, 1},  // t0: start sampled; register 1 ← pin 17; pass 1
        {1, 0, 1, 1},  // T/2: nothing changes on a falling edge
        {0, 1, 1, 0},  // T: register 9 ← pass 1; select 36 rises; 35 falls
        {0, 1, 1, 0},
        {0, 0, 0, 1},  // 2T: register 9 ← pass 2 (A); 35 rises: results valid
        {0, 0, 0, 1},
    }};

TEST(RtlSyncVcd, TimeUnitScopesAndNames) { expect_scopes_and_patent_names(sync); }
TEST(RtlSyncVcd, SaveFileSignalsAreAllInTheVcd) { expect_save_file_signals_in_the_vcd(sync); }

TEST(RtlSyncVcd, TimingTableHalfPeriodByHalfPeriod) {
  const Vcd vcd = make_vcd(sync, scratch_subdir("timing"));
  const std::string& dev = sync.device;
  const auto start_rises = vcd.rises(dev + ".pin27_start");
  const auto dones = vcd.rises(dev + ".pin35_done");
  ASSERT_EQ(start_rises.size(), examples.size());
  ASSERT_EQ(dones.size(), examples.size());
  std::vector<long long> starts;  // the start edges: a quarter period after start rises
  for (const long long r : start_rises) starts.push_back(r + period_ps / 4);
  for (const long long t0 : starts) {
    EXPECT_EQ(vcd.at(dev + ".pin27_start", t0), "1") << "start held over its edge at " << t0;
    EXPECT_EQ(vcd.at(dev + ".pin27_start", t0 + period_ps / 4), "0") << "start falls T/4 after its edge at " << t0;
  }
  expect_starts_and_results(vcd, dev, starts, dones, 2 * period_ps);  // 2 periods from the edge
  expect_timing_table(vcd, dev, sync_table, starts);
}

}  // namespace
}  // namespace specular
