// The progress line (issue 27): its text from counts and seconds computed here, drawn
// in place only when enabled, cleared at the end; and specular_tb prints none when
// standard error is not a terminal (a file here), so logs stay as they were.
#include <gtest/gtest.h>

#include <chrono>
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
