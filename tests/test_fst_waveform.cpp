// FST traces (issue 27): `--vcd NAME.fst` gives GTKWave's compressed format for every
// traced model. GTKWave itself, under a virtual X server as the VCD views are tested
// (test_vcd_waveform.cpp), opens the FST with the model's save file and shows, at
// every rising edge of 35, the same value for every displayed trace as it shows from
// the VCD of the same run (whose values those tests check against the formula).
// Skipped where GTKWave or Xvfb is not installed (scripts/setup.sh --gtkwave).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "support/scratch.h"
#include "support/subprocess.h"
#include "support/vcd.h"
#include "support/vcd_stretch.h"

namespace fs = std::filesystem;
using namespace specular::testing_support;

namespace {

const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
const fs::path source_dir = SPECULAR_SOURCE_DIR;

bool have_gtkwave() {
  return std::system("command -v gtkwave >/dev/null 2>&1 && command -v xvfb-run >/dev/null 2>&1 &&"
                     " command -v vcd2fst >/dev/null 2>&1") == 0;
}

/// What GTKWave shows for each displayed trace at each time: "time name" → value.
std::map<std::string, std::string> shown(const fs::path& dir, const fs::path& wave,
                                         const fs::path& gtkw, const std::vector<long long>& times,
                                         const std::string& tag) {
  const fs::path script = dir / (tag + ".tcl"), output = dir / (tag + ".txt");
  std::ofstream tcl(script);
  tcl << "foreach t {";
  for (const long long t : times) tcl << ' ' << t;
  tcl << " } {\n  gtkwave::setMarker $t\n  foreach s [gtkwave::getDisplayedSignals] {\n"
         "    puts \"shown $t $s = [gtkwave::getTraceValueAtMarkerFromName $s]\"\n  }\n}\n"
         "gtkwave::/File/Quit\n";
  tcl.close();
  const std::string display = std::to_string(100 + (::getpid() * 2 + (tag == "fst")) % 5000);
  const std::string command = "cd '" + dir.string() + "' && timeout 120 xvfb-run -a -n " + display +
                              " gtkwave -S '" + script.string() + "' '" + wave.string() + "' '" +
                              gtkw.string() + "' >'" + output.string() + "' 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << slurp(output);
  std::map<std::string, std::string> values;
  std::istringstream lines(slurp(output));
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string word, t, name, equals, value;
    if (words >> word >> t >> name >> equals >> value && word == "shown" && equals == "=")
      values[t + " " + name] = value;
  }
  return values;
}

void expect_fst_shows_as_vcd(const std::string& model, const std::string& gtkw) {
  if (!have_gtkwave()) GTEST_SKIP() << "GTKWave, vcd2fst or Xvfb not installed (scripts/setup.sh --gtkwave)";
  const fs::path dir = scratch_dir();
  const fs::path vcd = dir / "run.vcd", fst = dir / "run.fst";
  for (const fs::path& file : {vcd, fst}) {
    const Outcome r = run_command("cd '" + source_dir.string() + "' && '" + tb + "' --model " + model +
                                      " --input waveforms/example.csv --vcd '" + file.string() + "'",
                                  dir, file.extension().string().substr(1));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  // An FST is not a VCD: GTKWave's compressed format starts with its header block (0).
  std::ifstream in(fst, std::ios::binary);
  ASSERT_EQ(in.get(), 0);
  EXPECT_LT(fs::file_size(fst), fs::file_size(vcd));

  const Vcd parsed = parse_vcd(slurp(vcd));
  const auto times = parsed.rises(var_named(parsed, "pin35_done"));
  ASSERT_EQ(times.size(), 4u);  // waveforms/example.csv's operations
  const fs::path save = source_dir / "waveforms" / gtkw;
  const auto from_vcd = shown(dir, vcd, save, times, "vcd");
  const auto from_fst = shown(dir, fst, save, times, "fst");
  EXPECT_GT(from_vcd.size(), 4u * 10u);  // every displayed trace at four instants
  EXPECT_EQ(from_fst, from_vcd);
}

TEST(FstWaveform, PinFstOpensWithItsSaveFile) { expect_fst_shows_as_vcd("pin", "specular.gtkw"); }
#ifdef SPECULAR_HAS_RTL_TWIN
TEST(FstWaveform, RtlFstOpensWithItsSaveFile) { expect_fst_shows_as_vcd("rtl", "specular_rtl.gtkw"); }
TEST(FstWaveform, RtlSyncFstOpensWithItsSaveFile) {
  expect_fst_shows_as_vcd("rtl-sync", "specular_rtl_sync.gtkw");
}
#endif

// A window as FST: the same conversion after the window closes.
TEST(FstWaveform, WindowAsFst) {
  if (!have_gtkwave()) GTEST_SKIP() << "vcd2fst not installed (scripts/setup.sh --gtkwave)";
  const fs::path dir = scratch_dir();
  const fs::path fst = dir / "w.fst", back = dir / "back.vcd";
  const Outcome r = run_command("'" + tb + "' --random 30 --vcd '" + fst.string() + "' --trace-ops 10:3", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(std::system(("fst2vcd '" + fst.string() + "' >'" + back.string() + "' 2>/dev/null").c_str()), 0);
  const Vcd window = parse_vcd(slurp(back));
  EXPECT_EQ(window.rises(var_named(window, "pin35_done")).size(), 3u);
  // Nothing but the .fst is left in the folder (no VCD beside it).
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.path().extension() == ".vcd" ? 0 : 1;
  EXPECT_EQ(files, 1u);
}

}  // namespace
