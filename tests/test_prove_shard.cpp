// specular_prove (issue 25): the exhaustive proofs as a command, sharded by n as
// tests/support/operation_shard.h splits the long tests. The unsharded proof is the
// reference: the merge of every shard's partial prints its report bit for bit, with
// its exit status; a missing, duplicated or mismatched shard is refused by name. The
// quick form proves every 4096th cos code (--cos-stride): the same code paths, 17
// codes x 1000 n per device.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/operation_shard.h"
#include "support/scratch.h"
#include "support/subprocess.h"

using specular::testing_support::OperationShard;
using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::scratch_subdir;
namespace fs = std::filesystem;

namespace {

const std::string prove = std::string(SPECULAR_BINARY_DIR) + "/tools/prove/specular_prove";

Outcome run_prove(const std::string& arguments, const fs::path& dir) {
  return run_command(prove + " " + arguments, dir, "prove");
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

}  // namespace

#ifdef SPECULAR_HAS_RTL_TWIN
TEST(ProveShard, MergedShardsEqualTheUnshardedProof) {
  for (const std::string model : {"rtl", "rtl-sync"}) {
    SCOPED_TRACE(model);
    const fs::path dir = scratch_subdir("merge_" + model);
    const std::string run = "--model " + model + " --cos-stride 16384";
    const Outcome whole = run_prove(run + " --partial " + q(dir / "whole.json"), dir);
    ASSERT_EQ(whole.status, 0) << whole.err;
    // 24 devices, 23 buildable (the core refuses device-energy/literal/patent), each
    // 5 cos codes (0, 16384, ..., 65536) x 1000 n.
    EXPECT_NE(whole.out.find("24 device(s)"), std::string::npos) << whole.out;
    EXPECT_NE(whole.out.find("device-energy/literal/patent: refused, as the core refuses it  PASS"),
              std::string::npos) << whole.out;
    EXPECT_NE(whole.out.find("patent/clamp/patent: 5000 operations, 0 differ, 0 off timing  PASS"),
              std::string::npos) << whole.out;
    std::string merge = "--merge";
    for (int i = 4; i >= 0; --i) {
      const fs::path partial = dir / ("p" + std::to_string(i) + ".json");
      const Outcome shard = run_prove(run + " --shard " + std::to_string(i) + "/5 --partial " + q(partial), dir);
      ASSERT_EQ(shard.status, 0) << shard.err;
      merge += " " + q(partial);
    }
    const Outcome merged = run_prove(merge, dir);
    EXPECT_EQ(merged.status, 0) << merged.err;
    EXPECT_EQ(merged.out, whole.out);
  }
}

TEST(ProveShard, ShardCoversTheNOfOperationShard) {
  const fs::path dir = scratch_subdir("cover");
  const OperationShard shard{2, 7};
  const Outcome r = run_prove("--model rtl --device none/literal/minimax --cos-stride 4096 --shard 2/7", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string expected = "none/literal/minimax: " + std::to_string(17 * shard.covered(1, 1000)) + " operations";
  EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
}

TEST(ProveShard, MergeReportsAShardsDifferenceAndRefusesBadSets) {
  const fs::path dir = scratch_subdir("refuse");
  const std::string run = "--model rtl --device patent/clamp/patent --cos-stride 4096";
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(run_prove(run + " --shard " + std::to_string(i) + "/3 --partial " + q(dir / ("p" + std::to_string(i) + ".json")), dir).status, 0);
  ASSERT_EQ(run_prove("--model rtl --device patent/clamp/patent --cos-stride 2048 --shard 2/3 --partial " + q(dir / "stride.json"), dir).status, 0);
  nlohmann::json j;
  std::ifstream(dir / "p1.json") >> j;
  j["commit"] = "feedface";
  std::ofstream(dir / "commit.json") << j.dump();
  // A difference in shard 1 (as a faulty model would leave it): the merge says FAIL,
  // names where, and exits 1.
  std::ifstream(dir / "p1.json") >> j;
  j["summary"]["devices"][0]["mismatches"] = 1;
  j["summary"]["devices"][0]["pass"] = false;
  j["summary"]["devices"][0]["first_miss"] = {{"at", 1003}, {"what", "n 2, cos code 0: norm39"}};
  std::ofstream(dir / "bad1.json") << j.dump();

  const Outcome fail = run_prove("--merge " + q(dir / "p0.json") + " " + q(dir / "bad1.json") + " " + q(dir / "p2.json"), dir);
  EXPECT_EQ(fail.status, 1) << fail.err;
  EXPECT_NE(fail.out.find("1 differ, 0 off timing, first at n 2, cos code 0: norm39  FAIL"), std::string::npos) << fail.out;

  const std::vector<std::pair<std::string, std::string>> cases = {
      {q(dir / "p0.json") + " " + q(dir / "p2.json"), "1 of 3 shards missing: 1/3"},
      {q(dir / "p0.json") + " " + q(dir / "p1.json") + " " + q(dir / "p1.json") + " " + q(dir / "p2.json"), "shard 1/3 is given twice"},
      {q(dir / "p0.json") + " " + q(dir / "p1.json") + " " + q(dir / "stride.json"), "stride.json' has other settings"},
      {q(dir / "p0.json") + " " + q(dir / "commit.json") + " " + q(dir / "p2.json"), "commit.json' comes from commit feedface"},
  };
  for (const auto& [files, expected] : cases) {
    const Outcome r = run_prove("--merge " + files, dir);
    EXPECT_EQ(r.status, 2) << files;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
  }
}
#endif

TEST(ProveShard, PinModelProofMergesAndUsageErrorsNameTheValue) {
  const fs::path dir = scratch_subdir("pin");
  const std::string run = "--model pin --device energy/literal/patent --cos-stride 4096";
  const Outcome whole = run_prove(run + " --shard 0/50", dir);  // n = 1, 51, ..., 951
  ASSERT_EQ(whole.status, 0) << whole.err;
  EXPECT_NE(whole.out.find("energy/literal/patent: 340 operations, 0 differ, 0 off timing  PASS"), std::string::npos) << whole.out;
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"--model pin", "give --device NAME"},
      {"--model core", "'core' is the reference itself"},
      {"--model rtl --device x/y/z", "--device: 'x/y/z' is not one of"},
      {"--model rtl --shard 3/3", "I = 3 is outside the allowed range [0, 2]"},
      {"--model rtl --shard 0/1001", "N = 1001 is outside the allowed range [1, 1000]"},
      {"--model rtl --cos-stride 0", "K = 0 is outside the allowed range [1, 65536]"},
      {"--device all", "--model is required"},
  };
  for (const auto& [args, expected] : bad) {
    const Outcome r = run_prove(args, dir);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << ": " << r.err;
  }
}
