// The numerical study on the farm (issue 25): specular_study --shard I/N runs the stages s
// with s mod N = I and --partial writes what a merge needs; --merge gathers a complete set
// into one folder that equals the unsharded run's, file for file and byte for byte, with
// the same summary (but its time); an incomplete or mismatched set is refused by name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/scratch.h"
#include "support/subprocess.h"

namespace {

namespace fs = std::filesystem;
using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::scratch_subdir;
using specular::testing_support::slurp;

const std::string study = SPECULAR_STUDY_EXE;

std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) files[e.path().filename().string()] = slurp(e.path());
  return files;
}

std::string without_time(const std::string& summary) {
  std::istringstream in(summary);
  std::string out;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("Study time:", 0) != 0) out += line + "\n";
  return out;
}

std::set<std::string> names(const std::map<std::string, std::string>& files) {
  std::set<std::string> n;
  for (const auto& f : files) n.insert(f.first);
  return n;
}

TEST(StudyShard, ThreeShardsMergeToTheUnshardedStudy) {
  const fs::path dir = scratch_subdir("study");
  const std::string common = "'" + study + "' --quick --quiet --workers 1";
  const Outcome whole = run_command(common + " --out '" + (dir / "whole").string() + "'", dir);
  ASSERT_EQ(whole.status, 0) << whole.err;
  // Which files each stage writes (the study's documented outputs), so which files
  // each of 3 shards must write: stages {0, 3}, {1, 4}, {2, 5}.
  const std::vector<std::set<std::string>> expected = {
      {"constants_search.csv", "energy_device_energy.csv"},
      {"error_curves.csv", "max_error_by_n.csv", "heatmap_device_clamp.csv", "heatmap_device_vs_formula.csv",
       "heatmap_schlick.csv", "heatmap_us5739820.csv", "widths.csv", "widths_near_one.csv"},
      {"energy_integrals.csv", "sphere_n1.csv", "sphere_n10.csv", "sphere_n100.csv", "sphere_n1000.csv"}};
  std::string partials;
  for (int i = 0; i < 3; ++i) {
    const std::string s = std::to_string(i);
    const Outcome r = run_command(common + " --shard " + s + "/3 --partial '" + (dir / ("p" + s + ".json")).string() +
                                      "' --out '" + (dir / ("s" + s)).string() + "'",
                                  dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(names(files_of(dir / ("s" + s))), expected[static_cast<std::size_t>(i)]) << "shard " << i;
  }
  const std::string p0 = "'" + (dir / "p0.json").string() + "'", p1 = "'" + (dir / "p1.json").string() + "'",
                    p2 = "'" + (dir / "p2.json").string() + "'";
  const Outcome merged = run_command("'" + study + "' --merge " + p2 + " " + p0 + " " + p1 + " --out '" +
                                         (dir / "merged").string() + "'",
                                     dir);
  ASSERT_EQ(merged.status, 0) << merged.err;
  const auto want = files_of(dir / "whole"), got = files_of(dir / "merged");
  EXPECT_EQ(names(got), names(want));
  for (const auto& f : want) {
    if (f.first == "summary.txt") continue;
    EXPECT_TRUE(got.count(f.first) && got.at(f.first) == f.second) << f.first << " differs from the unsharded run's";
  }
  ASSERT_TRUE(got.count("summary.txt"));
  EXPECT_EQ(without_time(got.at("summary.txt")), without_time(want.at("summary.txt")));
  EXPECT_EQ(without_time(merged.out), without_time(whole.out));
  EXPECT_NE(without_time(merged.out).find("Maximum |f - cos^n|"), std::string::npos) << merged.out;

  // Refused, exit 2, nothing written: a missing shard, a shard twice, other settings.
  const auto refused = [&](const std::string& files, const std::string& message, const std::string& tag) {
    const fs::path out = dir / ("refused-" + tag);
    const Outcome r = run_command("'" + study + "' --merge " + files + " --out '" + out.string() + "'", dir);
    EXPECT_EQ(r.status, 2) << tag << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << tag << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << tag;
  };
  refused(p0 + " " + p2, "1 of 3 shards missing: 1/3", "missing");
  refused(p0 + " " + p1 + " " + p1 + " " + p2, "shard 1/3 is given twice", "twice");
  std::string other = slurp(dir / "p1.json");
  const std::size_t at = other.find("\"quick\":true");
  ASSERT_NE(at, std::string::npos) << other;
  other.replace(at, 12, "\"quick\":false");
  std::ofstream(dir / "other.json") << other;
  refused(p0 + " '" + (dir / "other.json").string() + "' " + p2, "has other settings", "settings");
}

}  // namespace
