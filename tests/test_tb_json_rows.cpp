// specular_tb --format json's rows (issue 25 item 4): the rows stay on issue 27's
// buffered writer (nlohmann-json wrote them 3.4-3.7x slower, docs/farm.md), so this test
// reads every row of a sweep's JSON output with nlohmann-json and checks every value
// against the core and the double reference computed here: the device's codes and their
// real values, the reference figures to the bit, the cycles and the verdict.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "specular/core.h"
#include "specular/reference.h"
#include "support/scratch.h"
#include "support/subprocess.h"

namespace specular {
namespace {

namespace fs = std::filesystem;

std::uint64_t hex(const nlohmann::json& value) {
  const std::string text = value.get<std::string>();
  EXPECT_EQ(text.rfind("0x", 0), 0u) << text;
  return std::stoull(text.substr(2), nullptr, 16);
}

TEST(TbJsonRows, EveryRowOfASweepShardParsesAndEqualsTheCoreAndTheReference) {
  const fs::path dir = testing_support::scratch_subdir("json");
  const fs::path file = dir / "sweep.json";
  const std::string tb = std::string(SPECULAR_BINARY_DIR) + "/testbench/specular_tb";
  // Every 50th n (1, 51, ..., 951) x the sweep's 1021 cos values: 20 420 rows.
  const testing_support::Outcome r = testing_support::run_command(
      "'" + tb + "' --sweep --model core --policy energy --shard 0/50 --format json --output '" + file.string() + "'",
      dir);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(file);
  const nlohmann::json report = nlohmann::json::parse(in);  // throws on a malformed row
  const nlohmann::json& rows = report.at("results");
  ASSERT_EQ(rows.size(), 20u * 1021u);
  EXPECT_EQ(report.at("summary").at("count").get<std::size_t>(), rows.size());

  Config config;
  config.normalisation = Normalisation::energy;
  const Core core(config);
  const Formats& f = core.formats();
  std::set<unsigned> ns;
  std::size_t checked = 0;
  for (const nlohmann::json& row : rows) {
    ASSERT_EQ(row.size(), 25u) << row.dump();
    const unsigned n = row.at("n").get<unsigned>();
    ns.insert(n);
    Operands op;
    op.n = n;
    op.cos = static_cast<code_t>(hex(row.at("reg1_hex")));
    const std::array<unsigned, 3> rgb = {row.at("r").get<unsigned>(), row.at("g").get<unsigned>(),
                                         row.at("b").get<unsigned>()};
    for (int ch = 0; ch < 3; ++ch) op.rgb[ch] = rgb[ch];
    // Register 1 holds the stimulus' cos, rounded to U1.16.
    const double cos = row.at("cos").get<double>();
    ASSERT_EQ(op.cos, static_cast<code_t>(std::llround(cos * 65536.0))) << row.dump();
    const Result res = core.run(op);
    ASSERT_EQ(hex(row.at("reg9_pass1_hex")), static_cast<std::uint64_t>(res.reg9_pass1)) << row.dump();
    ASSERT_EQ(hex(row.at("reg9_pass2_hex")), static_cast<std::uint64_t>(res.reg9_pass2)) << row.dump();
    ASSERT_EQ(hex(row.at("pin24_hex")), static_cast<std::uint64_t>(res.out[0])) << row.dump();
    ASSERT_EQ(hex(row.at("pin25_hex")), static_cast<std::uint64_t>(res.out[1])) << row.dump();
    ASSERT_EQ(hex(row.at("pin26_hex")), static_cast<std::uint64_t>(res.out[2])) << row.dump();
    const double cos_q = static_cast<double>(op.cos) / 65536.0;
    ASSERT_EQ(row.at("cos_q").get<double>(), cos_q) << row.dump();
    ASSERT_EQ(row.at("approx").get<double>(), f.reg9.to_real(res.reg9_pass2)) << row.dump();
    ASSERT_EQ(row.at("norm").get<double>(), f.norm.to_real(res.norm39)) << row.dump();
    const char* out_keys[3] = {"out_r", "out_g", "out_b"};
    const char* ref_keys[3] = {"out_r_ref", "out_g_ref", "out_b_ref"};
    const reference::Figures ref =
        reference::evaluate(cos_q, n, {double(rgb[0]), double(rgb[1]), double(rgb[2])}, Normalisation::energy,
                            Saturation::clamp, f.cos.frac_bits);
    for (int ch = 0; ch < 3; ++ch) {
      ASSERT_EQ(row.at(out_keys[ch]).get<double>(), f.out.to_real(res.out[ch])) << row.dump();
      ASSERT_EQ(row.at(ref_keys[ch]).get<double>(), ref.out_ref[ch]) << row.dump();
    }
    ASSERT_EQ(row.at("approx_ref").get<double>(), ref.approx_ref) << row.dump();
    ASSERT_EQ(row.at("norm_ref").get<double>(), ref.norm_ref) << row.dump();
    ASSERT_EQ(row.at("norm_exact").get<double>(), ref.norm_exact) << row.dump();
    ASSERT_EQ(row.at("cycles").get<double>(), 2.5) << row.dump();
    // The verdict from the bounds of issue 2 (reference.h), applied here.
    const double k = reference::k(n, Normalisation::energy);
    bool pass = std::abs(f.reg9.to_real(res.reg9_pass2) - ref.approx_ref) <= reference::approx_tolerance() &&
                std::abs(f.norm.to_real(res.norm39) - ref.norm_ref) <= reference::norm_tolerance(k);
    for (int ch = 0; ch < 3; ++ch)
      pass = pass && std::abs(f.out.to_real(res.out[ch]) - ref.out_ref[ch]) <=
                         reference::out_tolerance(k, rgb[ch], f.out.to_real(1));
    ASSERT_EQ(row.at("pass").get<bool>(), pass) << row.dump();
    ++checked;
  }
  EXPECT_EQ(checked, 20u * 1021u);
  std::set<unsigned> want;
  for (unsigned n = 1; n <= 1000; n += 50) want.insert(n);
  EXPECT_EQ(ns, want);
}

}  // namespace
}  // namespace specular
