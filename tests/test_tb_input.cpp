// The testbench's stimulus sources: CSV files (comments, blank lines, header,
// malformed lines with their line numbers), the sweep grid and the random draw.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "input.h"
#include "usage_error.h"
#include "support/scratch.h"

using specular::Formats;
using specular::code_t;
using namespace specular::tb;

namespace {

const Formats formats{};

std::vector<Stimulus> read(const std::string& text) {
  std::istringstream in(text);
  return read_stimuli(in, "vectors.csv", formats);
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& text, std::vector<std::string> fragments) {
  const std::string message = error_of(text);
  ASSERT_FALSE(message.empty()) << "no error for:\n" << text;
  for (const std::string& f : fragments)
    EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' missing in: " << message;
}

}  // namespace

TEST(TbInput, ReadsLinesSkippingCommentsBlanksAndHeader) {
  const auto s = read(
      "# vectors for the RTL\n"
      "cos,n,r,g,b\n"
      "\n"
      "0.5, 10, 1, 2, 3\n"
      "   \t\n"
      "1,1000,255,0,128   # trailing comment\r\n"
      "0,1,0,0,0\n");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_DOUBLE_EQ(s[0].cos, 0.5);
  EXPECT_EQ(s[0].n, 10u);
  EXPECT_EQ(s[0].rgb, (std::array<unsigned, 3>{1, 2, 3}));
  // Register 1 holds round(cos·2^16) (U1.16).
  EXPECT_EQ(s[0].operands.cos, 32768);
  EXPECT_EQ(s[0].operands.n, 10);
  EXPECT_EQ(s[0].operands.rgb, (std::array<code_t, 3>{1, 2, 3}));
  EXPECT_EQ(s[1].operands.cos, 65536);
  EXPECT_EQ(s[1].n, 1000u);
  EXPECT_EQ(s[2].operands.cos, 0);
}

TEST(TbInput, QuantisesCosToNearestCode) {
  const auto s = read("0.7071067811865476,2,1,1,1\n");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].operands.cos, static_cast<code_t>(std::llround(0.7071067811865476 * 65536)));
}

TEST(TbInput, MalformedLinesNameFileAndLine) {
  expect_error("0.5,10,1,2,3\n0.5,10,1,2\n", {"vectors.csv:2", "expected 5 fields", "found 4"});
  expect_error("# c\n\n0.5,10,1,2,3,4\n", {"vectors.csv:3", "found 6"});
  expect_error("0.5,10,1,2,3\n0.5,10,1,2,", {"vectors.csv:2", "B = ''", "[0, 255]"});
  expect_error("0.5;10;1;2;3\n", {"vectors.csv:1", "found 1"});
}

TEST(TbInput, BadValuesNameValueRangeAndLine) {
  expect_error("0.5,0,1,2,3\n", {"vectors.csv:1", "n = 0", "[1, 1000]"});
  expect_error("\n0.5,1001,1,2,3\n", {"vectors.csv:2", "1001", "[1, 1000]"});
  expect_error("0.5,12abc,1,2,3\n", {"vectors.csv:1", "'12abc'", "[1, 1000]"});
  expect_error("1.01,3,1,2,3\n", {"vectors.csv:1", "1.01", "[0, 1]"});
  expect_error("nan,3,1,2,3\n", {"vectors.csv:1", "nan", "[0, 1]"});
  expect_error("x,3,1,2,3\n", {"vectors.csv:1", "'x'", "[0, 1]"});
  expect_error("0.5,3,1,2,256\n", {"vectors.csv:1", "B = 256", "[0, 255]"});
  expect_error("0.5,3,1,,3\n", {"vectors.csv:1", "G", "[0, 255]"});
}

TEST(TbInput, HeaderOnlyAllowedFirst) {
  expect_error("0.5,10,1,2,3\ncos,n,r,g,b\n", {"vectors.csv:2", "'cos'"});
}

TEST(TbInput, MissingEmptyAndDirectoryFiles) {
  auto file_error = [](const std::string& path) {
    try {
      read_stimuli_file(path, formats);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string missing = "/nonexistent-dir/vectors.csv";
  EXPECT_NE(file_error(missing).find(missing), std::string::npos);
  EXPECT_NE(file_error(missing).find("No such file"), std::string::npos);
  EXPECT_NE(file_error("/").find("directory"), std::string::npos);

  const std::string empty = specular::testing_support::scratch_file("empty.csv").string();
  std::ofstream(empty) << "# only a comment\n\n";
  EXPECT_NE(file_error(empty).find("no operations"), std::string::npos);
  std::remove(empty.c_str());

  const std::string good = specular::testing_support::scratch_file("good.csv").string();
  std::ofstream(good) << "0.25,4,10,20,30\n";
  EXPECT_EQ(read_stimuli_file(good, formats).size(), 1u);
  std::remove(good.c_str());
}

TEST(TbInput, SweepGridHasUniformPartAndDenseTail) {
  const std::vector<code_t> codes = sweep_cos_codes(formats);
  const std::set<code_t> grid(codes.begin(), codes.end());
  EXPECT_EQ(grid.size(), codes.size()) << "codes are unique";
  EXPECT_TRUE(std::is_sorted(codes.begin(), codes.end()));
  EXPECT_EQ(codes.front(), 0);
  EXPECT_EQ(codes.back(), 65536);
  for (code_t k = 0; k <= 512; ++k) EXPECT_TRUE(grid.count(k * 128)) << "uniform step 2^-9: " << k;
  for (code_t k = 1; k <= 512; ++k) EXPECT_TRUE(grid.count(65536 - k)) << "tail: 1 - " << k;
  // 513 uniform + 512 tail − 4 shared (k·128 for k = 1..4 below 1).
  EXPECT_EQ(codes.size(), 1021u);
}

TEST(TbInput, SweepSourceRunsNOuterCosInner) {
  SweepSource sweep(formats, {7, 8, 9});
  EXPECT_EQ(sweep.size(), 1021u * 1000u);
  std::vector<Stimulus> chunk;
  std::size_t total = 0;
  unsigned last_n = 0;
  code_t last_cos = -1;
  while (sweep.next(chunk, 4096)) {
    EXPECT_LE(chunk.size(), 4096u);
    for (const Stimulus& s : chunk) {
      if (s.n != last_n) {
        EXPECT_EQ(s.n, last_n + 1);
        EXPECT_EQ(s.operands.cos, 0);
        last_n = s.n;
      } else {
        EXPECT_GT(s.operands.cos, last_cos);
      }
      last_cos = s.operands.cos;
      EXPECT_DOUBLE_EQ(s.cos, std::ldexp(static_cast<double>(s.operands.cos), -16));
      EXPECT_EQ(s.rgb, (std::array<unsigned, 3>{7, 8, 9}));
    }
    total += chunk.size();
  }
  EXPECT_EQ(total, 1021000u);
  EXPECT_EQ(last_n, 1000u);
}

TEST(TbInput, RandomSourceIsSeededAndInRange) {
  auto draw_all = [](std::uint64_t seed) {
    RandomSource source(formats, 5000, seed);
    std::vector<Stimulus> all, chunk;
    while (source.next(chunk, 333)) all.insert(all.end(), chunk.begin(), chunk.end());
    return all;
  };
  const auto a = draw_all(42), b = draw_all(42), c = draw_all(43);
  ASSERT_EQ(a.size(), 5000u);
  bool differs = false;
  std::set<unsigned> ns;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].operands.cos, b[i].operands.cos);
    EXPECT_EQ(a[i].n, b[i].n);
    EXPECT_EQ(a[i].rgb, b[i].rgb);
    differs = differs || a[i].operands.cos != c[i].operands.cos || a[i].n != c[i].n;
    EXPECT_GE(a[i].operands.cos, 0);
    EXPECT_LE(a[i].operands.cos, 65536);
    EXPECT_GE(a[i].n, 1u);
    EXPECT_LE(a[i].n, 1000u);
    for (unsigned v : a[i].rgb) EXPECT_LE(v, 255u);
    ns.insert(a[i].n);
  }
  EXPECT_TRUE(differs) << "another seed gives other draws";
  EXPECT_GT(ns.size(), 900u) << "n covers its range";
}
