// specular_variant_error (issue 26, tools/variant_error/): a variant's error over
// every cos code × a range of n. The figures are recomputed here from the variant's
// results with an independent double reference (2π/(n+2)·cos^n, its product with 255,
// the patent's formula K(n)·(1 − ½·log2(1 − n·log2 cos)) clamped at 0), and the merge of
// shards must give the unsharded run's figures bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "specular/variants/variant.h"
#include "support/scratch.h"
#include "variant_error.h"

using namespace specular;
using namespace specular::tb;
using specular::testing_support::scratch_subdir;

namespace {

struct ToolRun {
  int status = -1;
  std::string out, err;
};

ToolRun run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  ToolRun r;
  r.status = run_variant_error(args, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

/// max, mean and place of an error, recomputed in plain loops.
struct Expected {
  double max = -1, sum = 0;
  long long code = 0;
  unsigned n = 0;
  std::size_t count = 0;
  void add(double e, long long c, unsigned nn) {
    sum += e;
    ++count;
    if (e > max) max = e, code = c, n = nn;
  }
};

}  // namespace

TEST(VariantError, FiguresAreTheIndependentlyComputedOnes) {
  const auto dir = scratch_subdir("figures");
  const std::string json = (dir / "e.json").string();
  const ToolRun r = run({"patent", "--n", "1:3", "--json", json});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto variant = variants::make_variant("patent");
  const double pi = std::acos(-1.0);
  Expected lobe, out, formula;
  for (unsigned n = 1; n <= 3; ++n)
    for (long long code = 0; code <= 65536; ++code) {
      Operands op;
      op.cos = code;
      op.n = n;
      op.rgb = {255, 255, 255};
      const variants::VariantResult v = variant->run(op);
      const double c = code / 65536.0, k = 2 * pi / (n + 2.0);
      const double exact = k * std::pow(c, double(n));
      const double log2c = code == 0 ? -16.0 : std::log2(c);
      const double a = std::max(0.0, 1 - 0.5 * std::log2(1 - n * log2c));
      const double lobe_real = double(v.lobe) / 1048576.0;
      lobe.add(std::abs(lobe_real - exact), code, n);
      for (int ch = 0; ch < 3; ++ch) out.add(std::abs(double(v.out[ch]) / 8192.0 - 255 * exact), code, n);
      formula.add(std::abs(lobe_real - k * a), code, n);
    }
  const nlohmann::json j = read_json(json);
  EXPECT_EQ(j.at("name"), "patent");
  EXPECT_EQ(j.at("operations"), 3 * 65537);
  EXPECT_GE(j.at("seconds").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j.at("lobe_max_abs").get<double>(), lobe.max);
  EXPECT_NEAR(j.at("lobe_mean_abs").get<double>(), lobe.sum / double(lobe.count), 1e-12);
  EXPECT_EQ(j.at("lobe_max_at").at("cos_code"), lobe.code);
  EXPECT_EQ(j.at("lobe_max_at").at("n"), lobe.n);
  EXPECT_DOUBLE_EQ(j.at("out_max_abs").get<double>(), out.max);
  EXPECT_NEAR(j.at("out_mean_abs").get<double>(), out.sum / double(out.count), 1e-9);
  EXPECT_EQ(j.at("out_max_at").at("cos_code"), out.code);
  EXPECT_EQ(j.at("out_max_at").at("n"), out.n);
  // The formula reference agrees with the double formula to its rounding (ulps).
  EXPECT_NEAR(j.at("patent_formula").at("lobe_max_abs").get<double>(), formula.max, 1e-12);
  // n = 1, cos = 1/8: A = 0, the lobe's largest miss 2π/3·1/8 (docs/accuracy.md).
  EXPECT_EQ(lobe.code, 8192);
  EXPECT_EQ(lobe.n, 1u);
}

TEST(VariantError, ShardsMergeIntoTheUnshardedFiguresBitForBit) {
  const auto dir = scratch_subdir("shards");
  const std::string whole = (dir / "whole.json").string(), merged = (dir / "merged.json").string();
  ASSERT_EQ(run({"patent", "--n", "3:9", "--json", whole}).status, 0);
  std::vector<std::string> merge{"--merge"};
  for (int i = 2; i >= 0; --i) {  // any order
    const std::string partial = (dir / ("p" + std::to_string(i) + ".json")).string();
    const ToolRun r = run({"patent", "--n", "3:9", "--shard", std::to_string(i) + "/3", "--partial", partial});
    ASSERT_EQ(r.status, 0) << r.err;
    merge.push_back(partial);
  }
  merge.insert(merge.end(), {"--json", merged});
  const ToolRun m = run(merge);
  ASSERT_EQ(m.status, 0) << m.err;
  nlohmann::json a = read_json(whole), b = read_json(merged);
  a.erase("seconds");
  b.erase("seconds");
  EXPECT_EQ(a.dump(), b.dump());
  // A set with a shard missing is refused, naming it.
  merge.erase(merge.begin() + 1);
  const ToolRun incomplete = run({merge.begin(), merge.end() - 2});
  EXPECT_EQ(incomplete.status, 2);
  EXPECT_NE(incomplete.err.find("2/3"), std::string::npos) << incomplete.err;
}

TEST(VariantError, BadCommandLinesAreRefused) {
  const ToolRun unknown = run({"no-such-design"});
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("unknown variant 'no-such-design' (known: patent"), std::string::npos) << unknown.err;
  EXPECT_EQ(run({"patent", "--n", "5:2"}).status, 2);
  EXPECT_EQ(run({"patent", "--shard", "0/2"}).status, 2);  // without --partial
  EXPECT_EQ(run({}).status, 2);
  // --all: every registered variant, in registry order, as a JSON array.
  const std::string all = (scratch_subdir("all") / "all.json").string();
  ASSERT_EQ(run({"--all", "--n", "7:7", "--json", all}).status, 0);
  const nlohmann::json array = read_json(all);
  ASSERT_EQ(array.size(), variants::variant_names().size());
  for (std::size_t i = 0; i < array.size(); ++i) {
    EXPECT_EQ(array[i].at("name"), variants::variant_names()[i]);
    EXPECT_EQ(array[i].at("operations"), 65537);
  }
  EXPECT_EQ(run({"--all", "--shard", "0/2"}).status, 2);
  const ToolRun list = run({"--list"});
  EXPECT_EQ(list.status, 0);
  EXPECT_EQ(list.out.substr(0, 7), "patent\n");
}
