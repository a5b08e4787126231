// The buffered CSV and JSON row writers (issue 27: rows at the model's pace) write
// the same bytes as the stream-inserting writers they replaced, kept here as the
// reference: every real in its shortest std::to_chars form, integers, hex codes at
// their widths. Over random rows of the core and over values chosen to reach each
// fast path's edge (zeros of both signs, integers near 10^5, a column repeated).
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "report.h"
#include "scoreboard.h"
#include "specular/core.h"

using namespace specular;
using namespace specular::tb;

namespace {

void put_real(std::ostream& out, double value) {  // the replaced writers' form
  char buffer[32];
  const auto done = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.write(buffer, done.ptr - buffer);
}

std::string csv_row(const Comparison& c, const Formats& f) {
  std::ostringstream out;
  put_real(out, c.stimulus.cos);
  out << ',' << c.stimulus.n << ',' << c.stimulus.rgb[0] << ',' << c.stimulus.rgb[1] << ','
      << c.stimulus.rgb[2];
  for (double v : {c.ref.cos_q, c.approx, c.ref.approx_ref, c.norm, c.ref.norm_ref,
                   c.ref.norm_exact, c.out[0], c.out[1], c.out[2], c.ref.out_ref[0],
                   c.ref.out_ref[1], c.ref.out_ref[2], c.cycles}) {
    out << ',';
    put_real(out, v);
  }
  out << ',' << hex_code(c.result.reg1, f.cos.width()) << ','
      << hex_code(c.result.reg9_pass1, f.reg9.width()) << ','
      << hex_code(c.result.reg9_pass2, f.reg9.width()) << ',' << hex_code(c.result.out[0], f.out.width())
      << ',' << hex_code(c.result.out[1], f.out.width()) << ','
      << hex_code(c.result.out[2], f.out.width()) << ',' << (c.pass() ? 1 : 0) << '\n';
  return out.str();
}

std::string json_row(const Comparison& c, const Formats& f) {
  std::ostringstream out;
  out << "    {\"cos\": ";
  put_real(out, c.stimulus.cos);
  out << ", \"n\": " << c.stimulus.n << ", \"r\": " << c.stimulus.rgb[0] << ", \"g\": "
      << c.stimulus.rgb[1] << ", \"b\": " << c.stimulus.rgb[2];
  const std::pair<const char*, double> reals[] = {
      {"cos_q", c.ref.cos_q}, {"approx", c.approx}, {"approx_ref", c.ref.approx_ref},
      {"norm", c.norm}, {"norm_ref", c.ref.norm_ref}, {"norm_exact", c.ref.norm_exact},
      {"out_r", c.out[0]}, {"out_g", c.out[1]}, {"out_b", c.out[2]},
      {"out_r_ref", c.ref.out_ref[0]}, {"out_g_ref", c.ref.out_ref[1]},
      {"out_b_ref", c.ref.out_ref[2]}, {"cycles", c.cycles}};
  for (const auto& [key, value] : reals) {
    out << ", \"" << key << "\": ";
    put_real(out, value);
  }
  out << ", \"reg1_hex\": \"" << hex_code(c.result.reg1, f.cos.width()) << "\", \"reg9_pass1_hex\": \""
      << hex_code(c.result.reg9_pass1, f.reg9.width()) << "\", \"reg9_pass2_hex\": \""
      << hex_code(c.result.reg9_pass2, f.reg9.width()) << "\", \"pin24_hex\": \""
      << hex_code(c.result.out[0], f.out.width()) << "\", \"pin25_hex\": \""
      << hex_code(c.result.out[1], f.out.width()) << "\", \"pin26_hex\": \""
      << hex_code(c.result.out[2], f.out.width()) << "\", \"pass\": " << (c.pass() ? "true" : "false")
      << '}';
  return out.str();
}

/// Random rows of the core, then rows whose reals are set to each fast path's edges.
std::vector<Comparison> rows() {
  const Core core;
  const Scoreboard scoreboard(core.config());
  std::mt19937_64 random(27);
  std::vector<Comparison> all;
  for (int i = 0; i < 5000; ++i) {
    Stimulus s;
    s.operands.cos = static_cast<code_t>(random() % 65537);
    s.operands.n = static_cast<code_t>(1 + random() % 1000);
    for (auto& ch : s.operands.rgb) ch = static_cast<code_t>(random() % 256);
    s.cos = core.formats().cos.to_real(s.operands.cos);
    s.n = static_cast<unsigned>(s.operands.n);
    for (int ch = 0; ch < 3; ++ch) s.rgb[ch] = static_cast<unsigned>(s.operands.rgb[ch]);
    all.push_back(scoreboard.compare(s, core.run(s.operands), 2.5));
  }
  const double edges[] = {0.0, -0.0, 1.0, -1.0, 99999.0, -99999.0, 100000.0, -100000.0,
                          1e5 - 0.5, 10000.0, 12345.0, 1e-7, 0.0001, 2.5, 1e300, -1e-300,
                          std::numeric_limits<double>::denorm_min(), 65536.0, 4e9};
  for (double a : edges)
    for (double b : {0.0, -0.0, 255.0, 0.125}) {
      Comparison c = all[all.size() % 5000];
      c.approx = a;
      c.norm = b;
      c.ref.norm_exact = a;
      c.out = {a, b, a};
      c.cycles = b;
      c.stimulus.cos = a;
      all.push_back(c);
      all.push_back(c);  // the same values again: each column's last text reused
    }
  return all;
}

TEST(ReportBytes, CsvRowsAreTheStreamWritersBytes) {
  const auto comparisons = rows();
  const Formats f{};
  std::ostringstream out, side;
  auto report = make_report(OutputFormat::csv, out, side);
  RunDescription run;
  report->begin(run);
  std::string expected = std::string(csv_header()) + "\n";
  for (std::size_t i = 0; i < comparisons.size(); ++i) {
    report->row(comparisons[i]);
    if (i % 777 == 0) report->flush();  // a flush in the middle changes nothing
    expected += csv_row(comparisons[i], f);
  }
  report->flush();
  EXPECT_EQ(out.str(), expected);
}

TEST(ReportBytes, JsonRowsAreTheStreamWritersBytes) {
  const auto comparisons = rows();
  const Formats f{};
  std::ostringstream out, side;
  auto report = make_report(OutputFormat::json, out, side);
  RunDescription run;
  report->begin(run);
  const std::size_t header = out.str().size();
  std::string expected;
  for (std::size_t i = 0; i < comparisons.size(); ++i) {
    report->row(comparisons[i]);
    expected += (i == 0 ? "\n" : ",\n") + json_row(comparisons[i], f);
  }
  report->flush();
  EXPECT_EQ(out.str().substr(header), expected);
}

}  // namespace
