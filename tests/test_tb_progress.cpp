// The progress line (issue 27): its text from counts and seconds computed here, drawn
// in place only when enabled, cleared at the end; and specular_tb prints none when
// standard error is not a terminal (a file here), so logs stay as they were.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

#include "progress.h"
#include "support/scratch.h"
#include "support/subprocess.h"

using namespace specular::tb;
using namespace specular::testing_support;

namespace {

TEST(TbProgress, LineHasDoneTotalRateAndTimeLeft) {
  // 250 000 of 1 021 000 in 2 s: 125 000/s, 771 000 left = 6.168 s.
  EXPECT_EQ(progress_line(250000, 1021000, 2.0),
            "  250,000 / 1,021,000 operations (24.5%), 125.0 k/s, 0:06 left");
  // 3 M/s: (14e9 - 3e6) / 3e6 = 4665.7 s left, an hour and more.
  EXPECT_EQ(progress_line(3000000, 14000000000ull, 1.0),
            "  3,000,000 / 14,000,000,000 operations (0.0%), 3.00 M/s, 1:17:46 left");
  EXPECT_EQ(progress_line(0, 10, 0.5), "  0 / 10 operations (0.0%)");
  EXPECT_EQ(progress_line(7, 7, 14.0), "  7 / 7 operations (100.0%), 0.5 /s, 0:00 left");
}

TEST(TbProgress, UnitAndLabelNameWhatIsCounted) {
  // 3 of 12 in 6 s: 0.5 /s, 9 left = 18 s.
  EXPECT_EQ(progress_line(3, 12, 6.0, "items", "error study"),
            "  error study: 3 / 12 items (25.0%), 0.5 /s, 0:18 left");
  std::ostringstream out;
  Progress progress(out, 4, true, "periods tried", "gatesim");
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  progress.update(1);
  EXPECT_EQ(out.str().rfind("\r  gatesim: 1 / 4 periods tried (25.0%), ", 0), 0u) << out.str();
}

// The scripts' progress (scripts/flows/gatelevel/gatesim.sh): the same line through specular_progress.
TEST(TbProgress, ToolPrintsTheLineAndRefusesBadValues) {
  const std::string tool = std::string(SPECULAR_BINARY_DIR) + "/tools/progress/specular_progress";
  const auto dir = scratch_dir();
  const Outcome ok = run_command("'" + tool + "' 250000 1021000 2", dir, "ok");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(ok.out, "  250,000 / 1,021,000 operations (24.5%), 125.0 k/s, 0:06 left\n");
  // 2 periods of 9 in 100 s: 0.02 /s, 7 left = 350 s.
  const Outcome named = run_command("'" + tool + "' 2 9 100 'periods tried' gatesim", dir, "named");
  EXPECT_EQ(named.out, "  gatesim: 2 / 9 periods tried (22.2%), 0.0 /s, 5:50 left\n");
  const Outcome seconds = run_command("'" + tool + "' 5 10 soon", dir, "seconds");
  EXPECT_EQ(seconds.status, 2);
  EXPECT_NE(seconds.err.find("SECONDS: 'soon' is not a number"), std::string::npos) << seconds.err;
  EXPECT_NE(seconds.err.find("from 0 to 1e9"), std::string::npos) << seconds.err;
  const Outcome done = run_command("'" + tool + "' -1 10 1", dir, "done");
  EXPECT_EQ(done.status, 2);
  EXPECT_NE(done.err.find("DONE: '-1' is not a whole number"), std::string::npos) << done.err;
  const Outcome count = run_command("'" + tool + "' 1 2", dir, "count");
  EXPECT_EQ(count.status, 2);
  EXPECT_NE(count.err.find("SECONDS is required"), std::string::npos) << count.err;
  const Outcome extra = run_command("'" + tool + "' 1 2 3 u l more", dir, "extra");
  EXPECT_EQ(extra.status, 2);
  EXPECT_NE(extra.err.find("unexpected argument 'more'"), std::string::npos) << extra.err;
  const Outcome version = run_command("'" + tool + "' --version", dir, "version");
  EXPECT_EQ(version.status, 0);
  EXPECT_TRUE(std::regex_match(version.out, std::regex("specular_progress [0-9]+\\.[0-9]+\\.[0-9]+\n")))
      << version.out;
}

// The soak's stages: no progress line when standard error is a file, none with --quiet
// on a terminal (script(1) gives the run one).
TEST(TbProgress, SoakFollowsTheSameRule) {
  const std::string soak = std::string(SPECULAR_BINARY_DIR) + "/tools/soak/specular_soak";
  const auto dir = scratch_dir();
  const Outcome file = run_command("'" + soak + "' --core 20000 --pin 0 --tlm 0 --tlm-pin 0", dir, "file");
  EXPECT_EQ(file.status, 0) << file.err;
  EXPECT_EQ(file.err.find('\r'), std::string::npos) << file.err;
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "script(1) not installed";
  const Outcome quiet = run_command("script -qec \"'" + soak + "' --core 20000 --pin 0 --tlm 0 --tlm-pin 0 "
                                    "--quiet\" /dev/null", dir, "quiet");
  EXPECT_EQ(quiet.status, 0) << quiet.out;
  EXPECT_NE(quiet.out.find("core: ops=20000"), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("operations ("), std::string::npos) << quiet.out;
}

TEST(TbProgress, DrawnInPlaceAtMostTwiceASecondAndCleared) {
  std::ostringstream out;
  Progress progress(out, 100, true);
  progress.update(10);  // at once: not yet
  EXPECT_EQ(out.str(), "");
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  progress.update(50);
  const std::string drawn = out.str();
  EXPECT_EQ(drawn.rfind("\r  50 / 100 operations (50.0%), ", 0), 0u) << drawn;
  EXPECT_NE(drawn.find(" left\033[K"), std::string::npos) << drawn;
  progress.update(60);  // within half a second of the last: not drawn
  EXPECT_EQ(out.str(), drawn);
  progress.finish();
  EXPECT_EQ(out.str(), drawn + "\r\033[K");

  std::ostringstream quiet;
  Progress off(quiet, 100, false);
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  off.update(50);
  off.finish();
  EXPECT_EQ(quiet.str(), "");
}

TEST(TbProgress, NoProgressWhenStandardErrorIsAFile) {
  const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
  const Outcome r = run_command("'" + tb + "' --model core --sweep --format csv --output rows.csv",
                                scratch_dir());
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  EXPECT_EQ(r.err.rfind("summary: 1021000 computation(s)", 0), 0u) << r.err;
}

}  // namespace

// specular_prove (the farm's proof tasks, issue 25) follows the same rule: no progress
// line when standard error is a file, one on a terminal (script(1) gives the run one;
// the proof of 8 193 000 operations takes over a second, the line is drawn every half
// second), none with --quiet there.
TEST(TbProgress, ProveFollowsTheSameRule) {
  const std::string prove = std::string(SPECULAR_BINARY_DIR) + "/tools/prove/specular_prove";
  const std::string arguments = " --model rtl-sync --device patent/clamp/patent --cos-stride 8";
  const auto dir = scratch_dir();
  const Outcome file = run_command("'" + prove + "'" + arguments, dir, "file");
  EXPECT_EQ(file.status, 0) << file.err;
  EXPECT_NE(file.out.find("8193000 operations"), std::string::npos) << file.out;
  EXPECT_EQ(file.err.find('\r'), std::string::npos) << file.err;
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "script(1) not installed";
  const Outcome terminal = run_command("script -qec \"'" + prove + "'" + arguments + "\" /dev/null",
                                       dir, "terminal");
  EXPECT_EQ(terminal.status, 0) << terminal.out;
  EXPECT_NE(terminal.out.find("operations ("), std::string::npos) << terminal.out;
  const Outcome quiet = run_command("script -qec \"'" + prove + "'" + arguments + " --quiet\" /dev/null",
                                    dir, "quiet");
  EXPECT_EQ(quiet.status, 0) << quiet.out;
  EXPECT_NE(quiet.out.find("PASS"), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("operations ("), std::string::npos) << quiet.out;
}
