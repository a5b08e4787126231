// FST written by Verilator for the RTL twins (issue 27): `--vcd NAME.fst` with --model
// rtl or rtl-sync runs the twin verilated with --trace-fst (twin/CMakeLists.txt), so no
// VCD is written and GTKWave's vcd2fst is not needed (a PATH without it: the twins
// write their FST, the pin model, which converts, refuses naming the package). The
// FST holds, net by net, the value changes of the VCD of the same run (read back with
// GTKWave's fst2vcd), for a whole run and for a window. GTKWave opening it with the save
// files: test_fst_waveform.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "specular/twin/rtl_sync_device.h"
#include "support/scratch.h"
#include "support/subprocess.h"
#include "support/vcd.h"

namespace fs = std::filesystem;
using namespace specular::testing_support;

namespace {

#ifdef SPECULAR_HAS_RTL_TWIN
const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";

bool have_fst2vcd() { return std::system("command -v fst2vcd >/dev/null 2>&1") == 0; }

/// Every net's value changes, by its full name (scope.name), as the file holds them.
std::map<std::string, std::vector<std::pair<long long, std::string>>> nets(const Vcd& vcd) {
  std::map<std::string, std::vector<std::pair<long long, std::string>>> by_name;
  for (const Vcd::Var& v : vcd.vars) by_name[v.full()] = vcd.of(v.full());
  return by_name;
}

/// Runs the twin twice, VCD and FST, with `args`; PATH holds no vcd2fst.
void expect_fst_as_vcd(const std::string& model, const std::string& args, std::size_t rises) {
  const fs::path dir = scratch_dir(), traces = dir / "traces";
  fs::create_directories(traces);
  const fs::path vcd = traces / "run.vcd", fst = traces / "run.fst", back = dir / "back.vcd";
  for (const fs::path& file : {vcd, fst}) {
    const Outcome r = run_command("PATH='" + dir.string() + "' '" + tb + "' --model " + model + " " +
                                      args + " --vcd '" + file.string() + "'",
                                  dir, file.extension().string().substr(1));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  std::ifstream in(fst, std::ios::binary);
  ASSERT_EQ(in.get(), 0);  // FST's header block, not a VCD's text
  in.close();
  EXPECT_LT(fs::file_size(fst) * 4, fs::file_size(vcd));
  // Nothing else is left: no VCD beside the FST, no temporary file.
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(traces)) files += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 2u);  // run.vcd and run.fst
  if (!have_fst2vcd()) GTEST_SKIP() << "fst2vcd not installed (scripts/setup.sh --gtkwave)";
  ASSERT_EQ(std::system(("fst2vcd '" + fst.string() + "' >'" + back.string() + "' 2>/dev/null").c_str()), 0);
  const Vcd from_vcd = parse_vcd(slurp(vcd)), from_fst = parse_vcd(slurp(back));
  const auto want = nets(from_vcd), got = nets(from_fst);
  ASSERT_GT(want.size(), 30u);  // pins, Fig. 1's buses, the control unit
  EXPECT_EQ(got.size(), want.size());
  for (const auto& [name, changes] : want) {
    const auto it = got.find(name);
    ASSERT_NE(it, got.end()) << name << " is not in the FST";
    EXPECT_EQ(it->second, changes) << name;
  }
  EXPECT_EQ(from_fst.rises("TOP.pin35_done").size(), rises);
}

TEST(TwinFst, RtlWholeRunAsItsVcd) { expect_fst_as_vcd("rtl", "--random 40 --seed 5", 40); }
TEST(TwinFst, RtlSyncWholeRunAsItsVcd) { expect_fst_as_vcd("rtl-sync", "--random 40 --seed 5", 40); }
TEST(TwinFst, RtlWindowAsItsVcd) { expect_fst_as_vcd("rtl", "--random 40 --trace-ops 10:3", 3); }
TEST(TwinFst, RtlSyncWindowAsItsVcd) { expect_fst_as_vcd("rtl-sync", "--random 40 --trace-ops 10:3", 3); }

// The twin runs one verilated class from the start: a window during the simulation is
// opened in the format allow_tracing() chose, another name is refused naming both.
TEST(TwinFst, AWindowInTheOtherFormatIsRefused) {
  const fs::path dir = scratch_dir();
  specular::RtlSyncHarness harness("tb", specular::Config{}, sc_core::sc_time(10, sc_core::SC_NS), false);
  harness.dut.allow_tracing(true);
  sc_core::sc_start(sc_core::sc_time(100, sc_core::SC_NS));
  try {
    harness.dut.open_vcd((dir / "w.vcd").string());
    ADD_FAILURE() << "a VCD window opened on the FST model";
  } catch (const std::logic_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("RtlSyncDevice::open_vcd('"), std::string::npos) << what;
    EXPECT_NE(what.find("w.vcd'): the model writes FST"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir / "w.vcd"));
  harness.dut.open_vcd((dir / "w.fst").string());
  sc_core::sc_start(sc_core::sc_time(100, sc_core::SC_NS));
  harness.dut.close_vcd();
  std::ifstream in(dir / "w.fst", std::ios::binary);
  EXPECT_EQ(in.get(), 0);  // FST's header block
}

TEST(TwinFst, PinModelStillConvertsAndNeedsVcd2fst) {
  const fs::path dir = scratch_dir();
  const Outcome r = run_command("PATH='" + dir.string() + "' '" + tb + "' --random 4 --vcd run.fst", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("vcd2fst"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "run.fst"));
}
#endif

}  // namespace
