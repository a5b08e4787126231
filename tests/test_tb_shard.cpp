// specular_tb --shard I/N, --partial and --merge (issue 25). The unsharded run is the
// independent reference: its operations are what the shards' union must be, one for
// one, and its report is what the merge of the shards' partials must print, bit for
// bit (summary, maxima and their places, counts, PASS/FAIL, exit status). A merge
// refuses a missing, duplicated or mismatched shard, naming it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "input.h"
#include "options.h"
#include "shard.h"
#include "support/scratch.h"
#include "support/subprocess.h"
#include "testbench.h"
#include "usage_error.h"

using namespace specular;
using namespace specular::tb;
using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::scratch_subdir;
using specular::testing_support::slurp;
namespace fs = std::filesystem;

namespace {

struct TbRun {
  int status = -1;
  std::string out, err;
};

TbRun run_tb(const std::vector<std::string>& args, const ResultTap& tap = nullptr) {
  std::ostringstream out, err;
  TbRun r;
  r.status = run_testbench(args, out, err, tap);
  r.out = out.str();
  r.err = err.str();
  return r;
}

std::vector<std::string> plus(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// The report without its "run time" line and its energy line: the lines a merge
/// cannot reproduce (each shard's energy counts its first operation's toggles from a
/// reset device, the whole run's from the operation before it: docs/energy.md).
std::string without_run_time(const std::string& text) {
  std::istringstream in(text);
  std::string line, kept;
  while (std::getline(in, line))
    if (line.rfind("  run time ", 0) != 0 && line.rfind("  energy: ", 0) != 0) kept += line + '\n';
  return kept;
}

/// A summary without its energy (see without_run_time).
nlohmann::json without_energy(nlohmann::json summary) {
  summary.erase("energy_pj");
  return summary;
}

/// The header (first two lines) and the summary block (from "summary:") of a text report.
std::string header_and_summary(const std::string& text) {
  const std::size_t second = text.find('\n', text.find('\n') + 1);
  const std::size_t summary = text.find("\nsummary: ");
  if (second == std::string::npos || summary == std::string::npos) return "(no header or summary)\n" + text;
  return text.substr(0, second + 1) + without_run_time(text.substr(summary + 1));
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

/// Every operation a source yields, by index.
std::map<std::size_t, Stimulus> drain(StimulusSource& source) {
  std::map<std::size_t, Stimulus> all;
  std::vector<Stimulus> chunk;
  while (source.next(chunk, 97))
    for (const Stimulus& s : chunk) EXPECT_TRUE(all.emplace(s.index, s).second) << "index " << s.index << " twice";
  EXPECT_EQ(all.size(), source.size());
  return all;
}

bool same_operation(const Stimulus& a, const Stimulus& b) {
  return a.operands.cos == b.operands.cos && a.operands.n == b.operands.n &&
         a.operands.rgb == b.operands.rgb && a.n == b.n && a.rgb == b.rgb && a.cos == b.cos;
}

/// The union of the N shards' operations is the unsharded run's, operation for operation.
template <typename Make>
void expect_union_is_whole(Make make, std::size_t count) {
  auto whole_source = make(Shard{});
  const std::map<std::size_t, Stimulus> whole = drain(*whole_source);
  std::map<std::size_t, Stimulus> joined;
  for (std::size_t i = 0; i < count; ++i) {
    auto shard = make(Shard{i, count});
    for (const auto& [index, s] : drain(*shard))
      EXPECT_TRUE(joined.emplace(index, s).second) << "index " << index << " in two shards";
  }
  ASSERT_EQ(joined.size(), whole.size());
  std::size_t expected_index = 0;
  for (const auto& [index, s] : whole) {
    ASSERT_EQ(index, expected_index++);
    ASSERT_TRUE(same_operation(s, joined.at(index))) << "operation " << index << " differs";
  }
}

fs::path write_input(const fs::path& dir) {
  const fs::path input = dir / "ops.csv";
  std::ofstream file(input);
  file << "cos,n,r,g,b\n";
  // 40 operations, operation 3 repeated as operation 33 (a tie for the merge to break).
  for (int i = 0; i < 40; ++i) {
    const int j = i == 33 ? 3 : i;
    file << 0.5 + 0.0123 * j << ',' << 1 + 25 * j << ',' << (7 * j) % 256 << ",200," << (255 - j) << '\n';
  }
  return input;
}

}  // namespace

TEST(TbShard, ParseShardNamesTheValueAndTheRange) {
  EXPECT_EQ(parse_shard("2/5").index, 2u);
  EXPECT_EQ(parse_shard("2/5").count, 5u);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"5/5", "I = 5 is outside the allowed range [0, 4]"},
      {"-1/4", "[0, 3]"},
      {"1/0", "N = 0 is outside the allowed range [1, 1000000]"},
      {"3", "'3' is not I/N"},
      {"a/4", "'a'"},
  };
  for (const auto& [text, expected] : bad) {
    try {
      parse_shard(text);
      ADD_FAILURE() << text << " accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  const TbRun point = run_tb({"--cos", "0.5", "--n", "3", "--shard", "0/2", "--model", "core"});
  EXPECT_EQ(point.status, exit_usage);
  EXPECT_NE(point.err.find("--shard applies to --sweep, --random N and --input FILE"), std::string::npos) << point.err;
  const TbRun sweep = run_tb({"--sweep", "--shard", "0/1001", "--model", "core"});
  EXPECT_EQ(sweep.status, exit_usage);
  EXPECT_NE(sweep.err.find("N = 1001 is outside the allowed range [1, 1000] for --sweep"), std::string::npos) << sweep.err;
  const TbRun random = run_tb({"--random", "5", "--shard", "0/6", "--model", "core"});
  EXPECT_EQ(random.status, exit_usage);
  EXPECT_NE(random.err.find("N = 6 is outside the allowed range [1, 5] for --random 5"), std::string::npos) << random.err;
  const fs::path input = write_input(scratch_subdir("input"));
  const TbRun file = run_tb({"--input", input.string(), "--shard", "3/41", "--model", "core"});
  EXPECT_EQ(file.status, exit_usage);
  EXPECT_NE(file.err.find("N = 41 is outside the allowed range [1, 40]"), std::string::npos) << file.err;
}

TEST(TbShard, ShardsTogetherAreTheUnshardedOperations) {
  const Formats formats;
  expect_union_is_whole([&](const Shard& s) { return std::make_unique<SweepSource>(formats, std::array<unsigned, 3>{9, 8, 7}, s); }, 7);
  // Random: the same draws as the unsharded run (a shard skips draws, never reseeds).
  for (std::size_t count : {1u, 2u, 3u, 10u})
    expect_union_is_whole([&](const Shard& s) { return std::make_unique<RandomSource>(formats, 1001, 42, s); }, count);
  // A sweep shard holds exactly the n of tests/support/operation_shard.h's split.
  SweepSource shard(formats, {1, 2, 3}, Shard{2, 7});
  for (const auto& [index, s] : drain(shard)) ASSERT_EQ((s.n - 1) % 7, 2u) << "n " << s.n;
}

TEST(TbShard, MergedSweepEqualsTheUnshardedSweep) {
  const fs::path dir = scratch_subdir("sweep");
  const std::vector<std::string> run = {"--sweep", "--model", "core", "--policy", "energy", "--rgb", "200,100,31"};
  const TbRun whole = run_tb(plus(run, {"--partial", (dir / "whole.json").string()}));
  ASSERT_EQ(whole.status, exit_pass) << whole.err;
  std::vector<std::string> merge = {"--merge"};
  for (int i = 6; i >= 0; --i) {  // any order
    const std::string partial = (dir / ("p" + std::to_string(i) + ".json")).string();
    const TbRun shard = run_tb(plus(run, {"--shard", std::to_string(i) + "/7", "--partial", partial}));
    ASSERT_EQ(shard.status, exit_pass) << shard.err;
    merge.push_back(partial);
  }
  const TbRun merged = run_tb(plus(merge, {"--partial", (dir / "merged.json").string()}));
  ASSERT_EQ(merged.status, exit_pass) << merged.err;
  EXPECT_EQ(without_run_time(merged.out), without_run_time(whole.out));  // the whole text report, bit for bit
  const nlohmann::json w = read_json(dir / "whole.json"), m = read_json(dir / "merged.json");
  EXPECT_EQ(without_energy(m["summary"]), without_energy(w["summary"]));  // every maximum's place and the results' checksum
  // The energy: the shards' sum, each shard's first operation counted from reset.
  EXPECT_NEAR(m["summary"]["energy_pj"].get<double>(), w["summary"]["energy_pj"].get<double>(),
              0.01 * w["summary"]["energy_pj"].get<double>());
  EXPECT_EQ(m["settings"], w["settings"]);
  EXPECT_EQ(m["commit"], w["commit"]);
}

TEST(TbShard, MergedRandomRunWithFailuresEqualsTheUnshardedRun) {
  const fs::path dir = scratch_subdir("random");
  // Out of tolerance at operations 17, 600 and 1999, in three different shards: the
  // merge must say FAIL with the same counts, maxima and exit status.
  const ResultTap fault = [](const Stimulus& s, Result& r, double& cycles) {
    if (s.index == 17) r.norm39 += 1 << 12;
    if (s.index == 600) cycles = 3;
    if (s.index == 1999) r.out[1] += 1 << 20;
  };
  const std::vector<std::string> run = {"--random", "2000", "--seed", "7", "--model", "core"};
  for (const std::string format : {"text", "json"}) {
    SCOPED_TRACE(format);
    const TbRun whole = run_tb(plus(run, {"--format", format, "--partial", (dir / "whole.json").string()}), fault);
    ASSERT_EQ(whole.status, exit_out_of_tolerance) << whole.err;
    std::vector<std::string> merge = {"--merge", "--format", format, "--partial", (dir / "merged.json").string()};
    for (int i = 0; i < 4; ++i) {
      const std::string partial = (dir / ("p" + std::to_string(i) + ".json")).string();
      run_tb(plus(run, {"--shard", std::to_string(i) + "/4", "--format", format, "--partial", partial}), fault);
      merge.push_back(partial);
    }
    const TbRun merged = run_tb(merge);
    EXPECT_EQ(merged.status, exit_out_of_tolerance) << merged.err;
    if (format == "text") {
      EXPECT_EQ(header_and_summary(merged.out), header_and_summary(whole.out));
      EXPECT_NE(merged.out.find("summary: 2000 computation(s), 3 out of tolerance: FAIL"), std::string::npos) << merged.out;
    } else {
      const auto w = nlohmann::json::parse(whole.out), m = nlohmann::json::parse(merged.out);
      EXPECT_EQ(without_energy(m["summary"]), without_energy(w["summary"]));
      EXPECT_EQ(m["settings"], w["settings"]);
      EXPECT_EQ(m["summary"]["failures"], 3);
    }
    EXPECT_EQ(without_energy(read_json(dir / "merged.json")["summary"]),
              without_energy(read_json(dir / "whole.json")["summary"]));
  }
}

TEST(TbShard, MergedInputRunKeepsTheFirstOfEqualMaxima) {
  const fs::path dir = scratch_subdir("input");
  const fs::path input = write_input(dir);
  // Operations 3 and 33 are the same computation; both get the same fault, the run's
  // largest norm error. The unsharded run reports the first (index 3); so must a merge
  // that reads operation 33's shard first.
  const ResultTap fault = [](const Stimulus& s, Result& r, double&) {
    if (s.index == 3 || s.index == 33) r.norm39 += 1 << 14;
  };
  const std::vector<std::string> run = {"--input", input.string(), "--model", "core"};
  ASSERT_EQ(run_tb(plus(run, {"--partial", (dir / "whole.json").string()}), fault).status, exit_out_of_tolerance);
  std::vector<std::string> merge = {"--merge", "--partial", (dir / "merged.json").string()};
  for (int i = 3; i >= 0; --i) {
    const std::string partial = (dir / ("p" + std::to_string(i) + ".json")).string();
    run_tb(plus(run, {"--shard", std::to_string(i) + "/4", "--partial", partial}), fault);
    merge.push_back(partial);
  }
  EXPECT_EQ(run_tb(merge).status, exit_out_of_tolerance);
  const nlohmann::json w = read_json(dir / "whole.json"), m = read_json(dir / "merged.json");
  EXPECT_EQ(w["summary"]["max_norm_error"]["at"], 3);
  EXPECT_EQ(without_energy(m["summary"]), without_energy(w["summary"]));
}

TEST(TbShard, MergedSweepKeepsTheFirstOfEqualMaxima) {
  // cos = 0 gives out_ref = 0 at every n: the same fault on pin 24 at n = 2 (index 1021,
  // shard 1 of 7) and at n = 8 (index 7147, shard 0) is the same error. The unsharded
  // run reports n = 2, the first; the merge reads shard 0 first and must still say n 2.
  const fs::path dir = scratch_subdir("tie");
  const ResultTap fault = [](const Stimulus& s, Result& r, double&) {
    if (s.operands.cos == 0 && (s.n == 2 || s.n == 8)) r.out[0] += code_t{1} << 20;
  };
  const std::vector<std::string> run = {"--sweep", "--model", "core"};
  const TbRun whole = run_tb(run, fault);
  ASSERT_EQ(whole.status, exit_out_of_tolerance) << whole.err;
  ASSERT_NE(whole.out.find("max |out - out_ref|        = 1.2800e+02 at cos 0, n 2 "), std::string::npos) << whole.out;
  std::vector<std::string> merge = {"--merge"};
  for (int i = 0; i < 7; ++i) {
    const std::string partial = (dir / ("p" + std::to_string(i) + ".json")).string();
    run_tb(plus(run, {"--shard", std::to_string(i) + "/7", "--partial", partial}), fault);
    merge.push_back(partial);
  }
  const TbRun merged = run_tb(merge);
  EXPECT_EQ(merged.status, exit_out_of_tolerance) << merged.err;
  EXPECT_EQ(without_run_time(merged.out), without_run_time(whole.out));
}

TEST(TbShard, MergeRefusesAnIncompleteOrMismatchedSet) {
  const fs::path dir = scratch_subdir("refuse");
  const auto part = [&](const std::string& name) { return (dir / name).string(); };
  const std::vector<std::string> run = {"--random", "300", "--model", "core"};
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(run_tb(plus(run, {"--shard", std::to_string(i) + "/3", "--partial", part("p" + std::to_string(i) + ".json")})).status, exit_pass);
  ASSERT_EQ(run_tb(plus(run, {"--seed", "8", "--shard", "2/3", "--partial", part("seed8.json")})).status, exit_pass);
  ASSERT_EQ(run_tb(plus(run, {"--shard", "1/2", "--partial", part("of2.json")})).status, exit_pass);
  nlohmann::json other = read_json(part("p2.json"));
  other["commit"] = "0123456789abcdef";
  std::ofstream(part("commit.json")) << other.dump();
  std::ofstream(part("junk.json")) << "{\"kind\": 1";

  ASSERT_EQ(run_tb({"--merge", part("p0.json"), part("p1.json"), part("p2.json")}).status, exit_pass);
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
      {{part("p0.json"), part("p2.json")}, {"1 of 3 shards missing: 1/3"}},
      {{part("p0.json"), part("p1.json"), part("p1.json"), part("p2.json")},
       {"shard 1/3 is given twice", "p1.json"}},
      {{part("p0.json"), part("p1.json"), part("seed8.json")},
       {"seed8.json", "other settings", "--random 300 --seed 8"}},
      {{part("p0.json"), part("p1.json"), part("commit.json")},
       {"commit.json", "comes from commit 0123456789abcdef"}},
      {{part("p0.json"), part("p1.json"), part("p2.json"), part("of2.json")},
       {"of2.json", "one of 3 shards"}},
      {{part("p0.json"), part("junk.json")}, {"junk.json", "is not JSON"}},
      {{part("p0.json"), part("absent.json")}, {"cannot read", "absent.json"}},
  };
  for (const auto& [files, expected] : cases) {
    const TbRun r = run_tb(plus({"--merge"}, files));
    SCOPED_TRACE(expected.front());
    EXPECT_EQ(r.status, exit_usage);
    EXPECT_TRUE(r.out.empty()) << r.out;
    for (const std::string& text : expected) EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
  }
}

TEST(TbShard, PinModelShardsMergeToTheUnshardedRun) {
  // The pin model elaborates once per process: every run is a process of its own.
  const fs::path dir = scratch_subdir("pin");
  const std::string tb_path = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
  const std::string run = tb_path + " --random 60 --seed 3 --model pin";
  const Outcome whole = run_command(run + " --partial '" + (dir / "whole.json").string() + "'", dir, "whole");
  ASSERT_EQ(whole.status, 0) << whole.err;
  std::string merge = tb_path + " --merge";
  for (int i = 0; i < 2; ++i) {
    const std::string partial = (dir / ("p" + std::to_string(i) + ".json")).string();
    const Outcome shard = run_command(run + " --shard " + std::to_string(i) + "/2 --partial '" + partial + "'", dir, "shard");
    ASSERT_EQ(shard.status, 0) << shard.err;
    merge += " '" + partial + "'";
  }
  const Outcome merged = run_command(merge, dir, "merge");
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_EQ(header_and_summary(merged.out), header_and_summary(whole.out));
  EXPECT_NE(merged.out.find("summary: 60 computation(s), 0 out of tolerance: PASS"), std::string::npos) << merged.out;
}
