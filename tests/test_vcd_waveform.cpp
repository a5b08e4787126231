// The waveform a user opens (issue 2 item 9): `specular_tb --vcd` run as the README
// says, its VCD parsed here: time unit 1 ns or finer, scopes and names that carry the
// reference numbers of Fig. 1–3 (no signal_N), and every signal of
// waveforms/specular.gtkw present, so the saved view opens ready to read. The waves
// themselves are checked against the spec: 35 rises 2.5 periods after each start on 27,
// and register 9 holds the formula's value there. The save file shows the code buses
// as real numbers through GTKWave's fixed-point display; where GTKWave is installed,
// GTKWave itself (under Xvfb) is asked what it shows. `--real-views` adds real-valued
// *_real variables for other viewers.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/example_csv.h"
#include "support/scratch.h"
#include "support/subprocess.h"
#include "support/vcd.h"

namespace fs = std::filesystem;

namespace {

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
const fs::path source_dir = SPECULAR_SOURCE_DIR;
using specular::testing_support::scratch_subdir;
using specular::testing_support::Example;
using specular::testing_support::examples;

using specular::testing_support::code_at;
using specular::testing_support::slurp;
using specular::testing_support::parse_vcd;
using specular::testing_support::Vcd;

/// Runs the README's waveform command into `dir` (plus `extra` options); returns the
/// VCD's path.
fs::path make_vcd(const fs::path& dir, const std::string& extra = "") {
  const fs::path vcd = dir / "specular.vcd";
  const std::string command = "cd '" + source_dir.string() + "' && '" + tb +
                              "' --input waveforms/example.csv --vcd '" + vcd.string() + "' " +
                              extra + " >'" + (dir / "out.txt").string() + "' 2>&1";
  const int raw = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << slurp(dir / "out.txt");
  return vcd;
}

const std::string top = "SystemC.tb";
const std::string dut = "SystemC.tb.dut";
const std::string cu16 = "SystemC.tb.dut.cu16";

/// Fraction bits of each bus the save file shows as fixed point: the default formats
/// of docs/design.md, written out here (U1.16, S14.22, S5.22, U10.1, U8.16, S10.20,
/// S18.13); 0 for the integer buses.
struct Shown {
  std::string name;  ///< as the .gtkw names it
  bool is_signed;
  int frac_bits;
};
const std::vector<Shown>& shown_buses() {
  static const std::vector<Shown> buses = {
      {dut + ".reg1_q[16:0]", false, 16},       {dut + ".reg2_q[9:0]", false, 0},
      {dut + ".mux3_address[36:0]", true, 22},  {dut + ".rom5_log2[27:0]", true, 22},
      {dut + ".mux4_operand[17:0]", false, 8},  {dut + ".mul6_product[36:0]", true, 22},
      {dut + ".adder8_sum[36:0]", true, 22},    {dut + ".reg9_q[36:0]", true, 22},
      {dut + ".rom38_k[24:0]", false, 16},      {dut + ".mul39_norm[30:0]", true, 20},
      {dut + ".reg10_q[7:0]", false, 0},        {dut + ".reg11_q[7:0]", false, 0},
      {dut + ".reg12_q[7:0]", false, 0},        {top + ".pin24_r[31:0]", true, 13},
      {top + ".pin25_g[31:0]", true, 13},       {top + ".pin26_b[31:0]", true, 13}};
  return buses;
}
std::string without_range(const std::string& name) { return name.substr(0, name.find('[')); }

/// The formula on register 1's quantised cos (U1.16), clamped at 0 (the default policy).
double formula_a(const Example& e) {
  const double cos_q = std::round(e.cos * 65536) / 65536;
  return std::max(0.0, 1 - 0.5 * std::log2(1 - e.n * std::log2(cos_q)));
}

}  // namespace

TEST(VcdWaveform, TimeUnitScopesAndPatentNames) {
  const fs::path vcd_path = make_vcd(scratch_subdir("vcd"));
  ASSERT_TRUE(fs::exists(vcd_path));
  const std::string text = slurp(vcd_path);
  const Vcd vcd = parse_vcd(text);

  EXPECT_GT(vcd.timescale_seconds, 0);
  EXPECT_LE(vcd.timescale_seconds, 1e-9) << "time unit 1 ns or finer";
  EXPECT_EQ(vcd.scopes, (std::set<std::string>{"SystemC", top, dut, cu16}));
  EXPECT_EQ(text.find("signal_"), std::string::npos) << "no anonymous nets";

  // Every net names its block or pin by reference number: letters, the number, then
  // optionally a role (pin17_cos, reg9_q, q41, nand45_y, reg9_q_real).
  const std::regex patent_name("(pin|reg|mux|rom|mul|inv|adder|select|write|q|and|nand)"
                               "(1[7-9]|2[0-9]|3[0-5]|[1-9]|1[0-5]|3[6-9]|4[0-7])(_[a-z0-9_]+)?");
  for (const auto& v : vcd.vars)
    EXPECT_TRUE(std::regex_match(v.name, patent_name)) << v.full() << " does not read next to Fig. 1-3";

  // Pins 17-35 of the spec, as the SoC side drives and reads them.
  for (const char* pin : {"pin17_cos", "pin18_n", "pin19_h", "pin20_a", "pin21_r", "pin22_g",
                          "pin23_b", "pin24_r", "pin25_g", "pin26_b", "pin27_start", "pin28_clk",
                          "pin29_reset_n", "pin30_load_n", "pin31_load_r", "pin32_load_g",
                          "pin33_load_b", "pin34_carry", "pin35_done"})
    EXPECT_NE(vcd.find(top + "." + pin), nullptr) << pin;
  // Fig. 1: the output net of every block, at its bus width.
  const std::map<std::string, int> buses = {
      {"reg1_q", 17},        {"reg2_q", 10},       {"mux3_address", 37}, {"rom5_log2", 28},
      {"mux4_operand", 18},  {"mul6_product", 37}, {"inv7_inverted", 37}, {"adder8_sum", 37},
      {"reg9_q", 37},        {"reg10_q", 8},       {"reg11_q", 8},       {"reg12_q", 8},
      {"rom38_k", 25},       {"mul39_norm", 31}};
  for (const auto& [name, width] : buses) {
    const auto* v = vcd.find(dut + "." + name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_EQ(v->width, width) << name;
    EXPECT_EQ(v->range, "[" + std::to_string(width - 1) + ":0]") << name;
  }
  // Fig. 2: the flip-flops and gates of control unit 16, and its outputs 36 and 37.
  for (const char* net : {"q41", "q42", "q43_n", "and40_y", "inv44_y", "nand45_y"})
    EXPECT_NE(vcd.find(cu16 + "." + net), nullptr) << net;
  for (const char* net : {"select36", "write37"}) EXPECT_NE(vcd.find(dut + "." + net), nullptr) << net;
  // Codes only: the save file shows them as real numbers (fixed-point display), so no
  // real-valued variable is traced unless --real-views asks for it.
  for (const auto& v : vcd.vars) EXPECT_NE(v.type, "real") << v.full();
}

// --real-views: seven real-valued mirrors, each the code of its bus over 2^frac.
TEST(VcdWaveform, RealViewsOnRequestMirrorTheCodes) {
  const fs::path vcd_path =
      make_vcd(scratch_subdir("vcd"), "--real-views");
  const Vcd vcd = parse_vcd(slurp(vcd_path));
  const std::vector<std::pair<std::string, std::string>> views = {
      {"reg1_q_real", dut + ".reg1_q[16:0]"},          {"reg9_q_real", dut + ".reg9_q[36:0]"},
      {"rom38_k_real", dut + ".rom38_k[24:0]"},        {"mul39_norm_real", dut + ".mul39_norm[30:0]"},
      {"pin24_r_real", top + ".pin24_r[31:0]"},        {"pin25_g_real", top + ".pin25_g[31:0]"},
      {"pin26_b_real", top + ".pin26_b[31:0]"}};
  const auto dones = vcd.rises(top + ".pin35_done");
  ASSERT_EQ(dones.size(), examples.size());
  for (const auto& [view, bus] : views) {
    const auto* v = vcd.find(dut + "." + view);
    ASSERT_NE(v, nullptr) << view;
    EXPECT_EQ(v->type, "real") << view;
    const std::string& bus_name = bus;  // a lambda may not capture a structured binding before C++20
    const auto shown = std::find_if(shown_buses().begin(), shown_buses().end(),
                                    [&](const Shown& b) { return b.name == bus_name; });
    ASSERT_NE(shown, shown_buses().end()) << bus;
    for (const long long t : dones) {
      const std::string real = vcd.at(dut + "." + view, t);
      ASSERT_FALSE(real.empty()) << view;
      // SystemC writes a real with %.16g: equal to 16 significant digits.
      const double want = std::ldexp(
          static_cast<double>(code_at(vcd, without_range(bus), shown->is_signed, t)), -shown->frac_bits);
      EXPECT_NEAR(std::stod(real.substr(1)), want, 1e-15 * std::max(1.0, std::fabs(want)))
          << view << " at " << t;
    }
  }
}

TEST(VcdWaveform, WavesFollowTheTimingTableAndTheFormula) {
  const fs::path vcd_path = make_vcd(scratch_subdir("vcd"));
  const Vcd vcd = parse_vcd(slurp(vcd_path));
  const long long unit_ps = std::llround(vcd.timescale_seconds * 1e12);
  ASSERT_GT(unit_ps, 0);
  const long long T = 10000 / unit_ps;  // the default clock, 10 ns

  const std::vector<Example>& operations = examples;
  const auto starts = vcd.rises(top + ".pin27_start");
  const auto dones = vcd.rises(top + ".pin35_done");
  ASSERT_EQ(starts.size(), operations.size());
  ASSERT_EQ(dones.size(), operations.size());
  const auto clock_rises = vcd.rises(top + ".pin28_clk");
  const std::set<long long> clock_edges(clock_rises.begin(), clock_rises.end());
  for (std::size_t i = 0; i < operations.size(); ++i) {
    SCOPED_TRACE("operation " + std::to_string(i));
    EXPECT_TRUE(clock_edges.count(starts[i])) << "start rises with a rising clock edge";
    EXPECT_EQ(dones[i] - starts[i], 5 * T / 2) << "start to 35 rising: 2.5 periods";
    if (i > 0) {
      EXPECT_GE(starts[i] - starts[i - 1], 2 * T) << "protocol: starts 2 periods apart at least";
    }
    // Register 9 (S14.22) at 35↑: A = 1 − ½·log2(1 − n·log2 cos_q), cos_q in U1.16.
    const long long reg9 = code_at(vcd, dut + ".reg9_q", true, dones[i]);
    EXPECT_NEAR(std::ldexp(static_cast<double>(reg9), -22), formula_a(operations[i]),
                std::ldexp(1.0, -10));
  }
  // Two register-9 writes per operation on net 37, select 36 high for one period each.
  EXPECT_EQ(vcd.rises(dut + ".write37").size(), 2 * operations.size());
  EXPECT_EQ(vcd.rises(dut + ".select36").size(), operations.size());
}

TEST(VcdWaveform, GtkwaveSaveFileNamesOnlySignalsOfTheVcd) {
  const fs::path vcd_path = make_vcd(scratch_subdir("vcd"));
  const Vcd vcd = parse_vcd(slurp(vcd_path));
  std::set<std::string> names;
  for (const auto& v : vcd.vars) names.insert(v.gtkwave());

  std::ifstream save(source_dir / "waveforms" / "specular.gtkw");
  ASSERT_TRUE(save);
  std::string line, dumpfile;
  std::vector<std::string> signals, groups;
  // GTKWave's trace flags (its analyzer.h): the number format of the traces that follow
  // a '@' line, and the fixed-point shift of the traces after a [fpshift_count] line.
  constexpr unsigned long long tr_dec = 1ull << 2, tr_signed = 1ull << 10, tr_fpdecshift = 1ull << 30;
  unsigned long long flags = 0;
  int fpshift = 0;
  std::map<std::string, std::pair<unsigned long long, int>> display;  // signal → flags, shift
  while (std::getline(save, line)) {
    if (line.empty()) continue;
    if (line.rfind("[dumpfile]", 0) == 0) dumpfile = line;
    if (line.rfind("[fpshift_count]", 0) == 0) fpshift = std::stoi(line.substr(15));
    if (line[0] == '@') flags = std::stoull(line.substr(1), nullptr, 16);
    if (line[0] == '-' && line.size() > 1) groups.push_back(line.substr(1));
    if (line[0] == '[' || line[0] == '@' || line[0] == '-' || line[0] == '*') continue;
    signals.push_back(line);
    display[line] = {flags, fpshift};
  }
  ASSERT_GE(signals.size(), 16u);
  for (const std::string& s : signals) EXPECT_TRUE(names.count(s)) << s << " is not in the VCD";
  // Every bus of the datapath group as a number in its format: signed or unsigned
  // decimal, shifted by the format's fraction bits.
  for (const Shown& bus : shown_buses()) {
    const auto it = display.find(bus.name);
    ASSERT_NE(it, display.end()) << bus.name << " is not in the saved view";
    const auto [bus_flags, shift] = it->second;
    EXPECT_EQ((bus_flags & tr_signed) != 0, bus.is_signed) << bus.name;
    if (!bus.is_signed) {
      EXPECT_NE(bus_flags & tr_dec, 0u) << bus.name << ": unsigned decimal";
    }
    EXPECT_EQ((bus_flags & tr_fpdecshift) != 0, bus.frac_bits > 0) << bus.name;
    if (bus.frac_bits > 0) {
      EXPECT_EQ(shift, bus.frac_bits) << bus.name;
    }
  }
  // The control unit of Fig. 3 grouped: clock, start, reset, Q41-Q43, 36, 37, 35.
  EXPECT_NE(std::find(groups.begin(), groups.end(), "control unit 16 (Fig. 3)"), groups.end());
  EXPECT_NE(std::find(groups.begin(), groups.end(), "datapath (Fig. 1)"), groups.end());
  for (const char* s : {"SystemC.tb.pin28_clk", "SystemC.tb.pin27_start", "SystemC.tb.dut.cu16.q41",
                        "SystemC.tb.dut.cu16.q42", "SystemC.tb.dut.select36",
                        "SystemC.tb.dut.write37", "SystemC.tb.pin35_done"})
    EXPECT_NE(std::find(signals.begin(), signals.end(), s), signals.end()) << s;
  // The save file points at the VCD the README's command writes (build/specular.vcd),
  // relative to waveforms/.
  EXPECT_EQ(dumpfile, "[dumpfile] \"../build/specular.vcd\"");
  const std::string readme = slurp(source_dir / "README.md");
  EXPECT_NE(readme.find("--input waveforms/example.csv --vcd build/specular.vcd"), std::string::npos);
  EXPECT_NE(readme.find("gtkwave build/specular.vcd waveforms/specular.gtkw"), std::string::npos);
}

// GTKWave's own VCD reader (its vcd2fst/fst2vcd tools, installed by
// `scripts/setup.sh --gtkwave`) takes the file and keeps every name of the saved view
// and every edge of pin 35. Skipped where GTKWave is not installed.
TEST(VcdWaveform, GtkwaveReadsTheVcd) {
  if (std::system("command -v vcd2fst >/dev/null 2>&1 && command -v fst2vcd >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "GTKWave not installed (scripts/setup.sh --gtkwave)";
  const fs::path dir = scratch_subdir("vcd");
  const fs::path vcd_path = make_vcd(dir);
  const fs::path fst = dir / "specular.fst", back = dir / "back.vcd";
  const std::string command = "vcd2fst '" + vcd_path.string() + "' '" + fst.string() +
                              "' >/dev/null 2>&1 && fst2vcd '" + fst.string() + "' >'" +
                              back.string() + "' 2>/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Vcd original = parse_vcd(slurp(vcd_path)), read_back = parse_vcd(slurp(back));
  std::set<std::string> names, names_back;
  for (const auto& v : original.vars) names.insert(v.gtkwave());
  for (const auto& v : read_back.vars) names_back.insert(v.gtkwave());
  EXPECT_EQ(names_back, names);
  EXPECT_EQ(read_back.rises(top + ".pin35_done"), original.rises(top + ".pin35_done"));
  EXPECT_EQ(read_back.rises(top + ".pin35_done").size(), 4u);
}

// What GTKWave itself shows with the saved view: run under a virtual X server (Xvfb),
// it is asked by a Tcl script for the value of every displayed trace at each rising
// edge of 35 and of select 36, and those values must be the formula's (register 1 the
// quantised cos, register 9 pass 1 and A, ROM 38's K(n) = 2π/(n+2), K·A and the pins
// within their tolerances) and each bus's code over 2^frac. Skipped where GTKWave or Xvfb is not installed (scripts/setup.sh --gtkwave).
TEST(VcdWaveform, GtkwaveShowsTheBusesAsRealNumbers) {
  if (std::system("command -v gtkwave >/dev/null 2>&1 && command -v xvfb-run >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "GTKWave or Xvfb not installed (scripts/setup.sh --gtkwave)";
  const fs::path dir = scratch_subdir("vcd");
  const fs::path vcd_path = make_vcd(dir);
  const Vcd vcd = parse_vcd(slurp(vcd_path));
  const auto dones = vcd.rises(top + ".pin35_done");
  ASSERT_EQ(dones.size(), examples.size());
  // Pass 1 is in register 9 while select 36 rises; register 1 still holds this
  // operation's cos there (at 35↑ the next start may have loaded the next one).
  const auto selects = vcd.rises(dut + ".select36");
  ASSERT_EQ(selects.size(), examples.size());

  std::ofstream script(dir / "ask.tcl");
  script << "foreach t {";
  for (const long long t : dones) script << ' ' << t;
  for (const long long t : selects) script << ' ' << t;
  script << " } {\n"
            "  gtkwave::setMarker $t\n"
            "  foreach s [gtkwave::getDisplayedSignals] {\n"
            "    puts \"shown $t $s = [gtkwave::getTraceValueAtMarkerFromName $s]\"\n"
            "  }\n"
            "}\n"
            "gtkwave::/File/Quit\n";
  script.close();
  // xvfb-run -a looks for a free display from the one given: start each process at its
  // own (another run beside this one would race for :99).
  const std::string display = std::to_string(100 + ::getpid() % 5000);
  const std::string command = "cd '" + dir.string() + "' && timeout 120 xvfb-run -a -n " + display +
                              " gtkwave -S ask.tcl '" +
                              vcd_path.string() + "' '" +
                              (source_dir / "waveforms" / "specular.gtkw").string() +
                              "' >shown.txt 2>&1";
  const int status = std::system(command.c_str());
  const std::string output = slurp(dir / "shown.txt");
  ASSERT_EQ(status, 0) << command << "\n" << output;

  std::map<std::pair<long long, std::string>, std::string> shown;  // (time, name) → text
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string tag, name, equals, value;
    long long t = 0;
    if (words >> tag >> t >> name >> equals >> value && tag == "shown" && equals == "=")
      shown[{t, name}] = value;
  }
  ASSERT_FALSE(shown.empty()) << output;

  const auto number = [&](long long t, const std::string& name) {
    const auto it = shown.find({t, name});
    EXPECT_NE(it, shown.end()) << name << " at " << t << " not shown";
    return it == shown.end() ? std::nan("") : std::stod(it->second);
  };
  for (std::size_t i = 0; i < examples.size(); ++i) {
    const Example& e = examples[i];
    const long long t = dones[i];
    SCOPED_TRACE("operation " + std::to_string(i) + " at " + std::to_string(t));
    // Each bus: its code in the VCD over 2^frac (GTKWave prints 16 significant digits).
    for (const Shown& bus : shown_buses()) {
      const double want = std::ldexp(
          static_cast<double>(code_at(vcd, without_range(bus.name), bus.is_signed, t)), -bus.frac_bits);
      EXPECT_NEAR(number(t, bus.name), want, 1e-12 * std::max(1.0, std::fabs(want))) << bus.name;
    }
    // And the formula, computed here.
    const double cos_q = std::round(e.cos * 65536) / 65536;
    const double a = formula_a(e);
    const double k = 2 * M_PI / (e.n + 2);
    EXPECT_EQ(number(selects[i], dut + ".reg1_q[16:0]"), cos_q);
    EXPECT_NEAR(number(selects[i], dut + ".reg9_q[36:0]"), 1 - e.n * std::log2(cos_q),
                std::ldexp(1.0, -10) * e.n);  // pass 1: 1 − n·log2 cos_q
    EXPECT_EQ(number(t, dut + ".reg2_q[9:0]"), e.n);
    EXPECT_NEAR(number(t, dut + ".reg9_q[36:0]"), a, std::ldexp(1.0, -10));
    EXPECT_NEAR(number(t, dut + ".rom38_k[24:0]"), k, std::ldexp(1.0, -16));
    const double norm_bound = std::ldexp(1.0, -10) * std::max(1.0, k);
    EXPECT_NEAR(number(t, dut + ".mul39_norm[30:0]"), k * a, norm_bound);
    const char* pins[3] = {".pin24_r[31:0]", ".pin25_g[31:0]", ".pin26_b[31:0]"};
    const char* regs[3] = {".reg10_q[7:0]", ".reg11_q[7:0]", ".reg12_q[7:0]"};
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_EQ(number(t, dut + regs[ch]), e.rgb[ch]);
      EXPECT_NEAR(number(t, top + pins[ch]), k * a * e.rgb[ch],
                  norm_bound * e.rgb[ch] + std::ldexp(1.0, -13));
    }
  }
}
