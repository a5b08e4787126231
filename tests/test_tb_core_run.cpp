// specular_tb end to end on the core model, in process: CSV in, CSV out, every
// figure checked against the formula evaluated here in double precision.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "scoreboard.h"
#include "testbench.h"
#include "support/scratch.h"

using namespace specular::tb;

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) fields.push_back(field);
  return fields;
}

/// The patent's formula, written out again here (independent of the model and of
/// reference.cpp): A = 1 − ½·log2(1 − n·log2 cos), log2 0 := −16 (spec Decision).
double formula(double cos_q, unsigned n, bool clamp) {
  const double log2_cos = cos_q == 0 ? -16.0 : std::log2(cos_q);
  const double a = 1 - 0.5 * std::log2(1 - n * log2_cos);
  return clamp ? std::max(a, 0.0) : a;
}

double k_of(unsigned n, const std::string& policy) {
  if (policy == "patent") return 2 * M_PI / (n + 2);
  if (policy == "energy") return (n + 2) / (2 * M_PI);
  return 1;
}

struct Row {
  std::map<std::string, std::string> text;
  // strtod, not stod: a subnormal norm_exact (cos^1000) is valid, stod throws on it.
  double operator[](const std::string& key) const { return std::strtod(text.at(key).c_str(), nullptr); }
};

std::vector<Row> parse_csv(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  const auto header = split(line);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    const auto fields = split(line);
    EXPECT_EQ(fields.size(), header.size());
    Row row;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) row.text[header[i]] = fields[i];
    rows.push_back(row);
  }
  return rows;
}

/// Checks every row against the formula, under `policy` and `saturation`.
void check_rows(const std::vector<Row>& rows, const std::string& policy, bool clamp) {
  for (const Row& r : rows) {
    const unsigned n = static_cast<unsigned>(r["n"]);
    const double cos_q = std::round(r["cos"] * 65536) / 65536;  // register 1: U1.16
    const double k = k_of(n, policy);
    const double a_ref = formula(cos_q, n, clamp);
    SCOPED_TRACE("cos " + r.text.at("cos") + " n " + r.text.at("n"));
    EXPECT_DOUBLE_EQ(r["cos_q"], cos_q);
    EXPECT_NEAR(r["approx_ref"], a_ref, 1e-12);
    EXPECT_NEAR(r["norm_ref"], k * a_ref, 1e-12 * std::max(1.0, k));
    EXPECT_NEAR(r["norm_exact"], k * std::pow(cos_q, n), 1e-12 * std::max(1.0, k));
    EXPECT_NEAR(r["approx"], a_ref, std::ldexp(1.0, -10));
    EXPECT_NEAR(r["norm"], k * a_ref, std::ldexp(1.0, -10) * std::max(1.0, k));
    const char* channels[3] = {"r", "g", "b"};
    for (const char* ch : channels) {
      const double intensity = r[ch];
      EXPECT_NEAR(r[std::string("out_") + ch], k * a_ref * intensity,
                  std::ldexp(1.0, -10) * std::max(1.0, k) * intensity + std::ldexp(1.0, -13));
    }
    EXPECT_EQ(r["cycles"], 2.5);
    EXPECT_EQ(r.text.at("pass"), "1");
  }
}

std::string temp_file(const std::string& name, const std::string& content) {
  const std::string path = specular::testing_support::scratch_file(name).string();
  std::ofstream(path) << content;
  return path;
}

}  // namespace

TEST(TbCoreRun, InputFileEveryPolicyAgainstTheFormula) {
  const std::string input = temp_file("core_input.csv",
                                      "# edges and ordinary points\n"
                                      "0,1,255,255,255\n"
                                      "1,1,255,255,255\n"
                                      "0.99998474121,1000,255,128,0\n"
                                      "0.5,1,10,20,30\n"
                                      "0.125,1,1,1,1\n"
                                      "0.9,10,200,100,50\n"
                                      "0.7071,1000,3,2,1\n"
                                      "0.999,700,255,255,255\n"
                                      "0.3,2,100,100,100\n");
  for (const std::string policy : {"patent", "energy", "none"}) {
    for (const std::string saturation : {"clamp", "literal"}) {
      std::ostringstream out, err;
      const int status = run_testbench({"--model", "core", "--input", input, "--format", "csv",
                                        "--policy", policy, "--saturation", saturation},
                                       out, err);
      SCOPED_TRACE(policy + " " + saturation);
      EXPECT_EQ(status, exit_pass) << err.str();
      const auto rows = parse_csv(out.str());
      ASSERT_EQ(rows.size(), 9u);
      check_rows(rows, policy, saturation == "clamp");
    }
  }
}

TEST(TbCoreRun, RandomRunPassesAndMatchesTheFormula) {
  std::ostringstream out, err;
  EXPECT_EQ(run_testbench({"--model", "core", "--random", "3000", "--seed", "11", "--format", "csv"},
                          out, err),
            exit_pass)
      << err.str();
  const auto rows = parse_csv(out.str());
  ASSERT_EQ(rows.size(), 3000u);
  check_rows(rows, "patent", true);
  EXPECT_NE(err.str().find("summary: 3000 computation(s), 0 out of tolerance: PASS"), std::string::npos);
}

TEST(TbCoreRun, SweepSummaryCoversTheGrid) {
  std::ostringstream out, err;
  EXPECT_EQ(run_testbench({"--model", "core", "--sweep"}, out, err), exit_pass) << err.str();
  const std::string text = out.str();
  EXPECT_NE(text.find("summary: 1021000 computation(s), 0 out of tolerance: PASS"), std::string::npos)
      << text;
  EXPECT_NE(text.find("max |norm - norm_ref|"), std::string::npos);
  EXPECT_NE(text.find("max |norm - norm_exact|"), std::string::npos);
  // The formula's own worst error: 0.125 in A at x = −3, times K(1) = 2π/3 (patent policy).
  // It lies between two grid points, so the sweep finds a little less.
  const auto at = text.find("max |norm - norm_exact|");
  const double worst = std::stod(text.substr(text.find('=', at) + 1));
  EXPECT_LE(worst, 0.125 * 2 * M_PI / 3 + 1e-3);
  EXPECT_GE(worst, 0.9 * 0.125 * 2 * M_PI / 3);
}

TEST(TbCoreRun, ScoreboardFlagsAResultOutOfTolerance) {
  const specular::Config config;
  const specular::Core core(config);
  Scoreboard scoreboard(config);
  const Stimulus s = make_stimulus(core.formats(), 0.9, 10, {200, 100, 50}, "");
  specular::Result r = core.run(s.operands);
  EXPECT_TRUE(scoreboard.compare(s, r, 2.5).pass());
  // Register 9 off by 2^-9 (twice the tolerance): approx fails.
  specular::Result bad = r;
  bad.reg9_pass2 += std::int64_t{1} << (22 - 9);
  const Comparison c = scoreboard.compare(s, bad, 2.5);
  EXPECT_FALSE(c.approx_ok);
  EXPECT_FALSE(c.pass());
  // Wrong latency: cycles fail.
  EXPECT_FALSE(scoreboard.compare(s, r, 3.0).cycles_ok);
  // Pin 25 off by 1.0 in R, G, B units (tolerance here ≈ 0.1): out fails.
  specular::Result off = r;
  off.out[1] += std::int64_t{1} << 13;
  EXPECT_FALSE(scoreboard.compare(s, off, 2.5).out_ok);
  scoreboard.record(scoreboard.compare(s, r, 2.5));
  scoreboard.record(c);
  EXPECT_EQ(scoreboard.summary().count, 2u);
  EXPECT_EQ(scoreboard.summary().failures, 1u);
  EXPECT_EQ(scoreboard.summary().approx_failures, 1u);
  EXPECT_FALSE(scoreboard.summary().pass());
  EXPECT_NEAR(scoreboard.summary().approx.error, std::ldexp(1.0, -9), 1e-4);
}

TEST(TbCoreRun, UsageErrorsExitTwoWithTheMessage) {
  std::ostringstream out, err;
  EXPECT_EQ(run_testbench({"--model", "core", "--cos", "0.5", "--n", "1001"}, out, err), exit_usage);
  EXPECT_NE(err.str().find("1001"), std::string::npos);
  EXPECT_NE(err.str().find("[1, 1000]"), std::string::npos);
  EXPECT_TRUE(out.str().empty());
}
