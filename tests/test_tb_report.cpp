// Report writers: hex codes at bus widths, the CSV header and rows, JSON that a
// strict parser accepts with the documented structure, the text summary.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "report.h"
#include "scoreboard.h"
#include "specular/core.h"
#include "specular/reference.h"

using specular::Config;
using specular::Core;
using specular::Formats;
using namespace specular::tb;

namespace {

// ---- a small strict JSON parser (RFC 8259 subset: no \u surrogates needed) ----
struct Json {
  enum Kind { null, boolean, number, string, array, object } kind = null;
  bool flag = false;
  double value = 0;
  std::string text;
  std::vector<Json> items;
  std::map<std::string, Json> fields;
  const Json& operator[](const std::string& key) const {
    const auto it = fields.find(key);
    if (kind != object || it == fields.end()) throw std::runtime_error("no key " + key);
    return it->second;
  }
};

class JsonParser {
 public:
  explicit JsonParser(const std::string& text) : t_(text) {}
  Json parse() {
    Json j = value();
    blanks();
    if (i_ != t_.size()) fail("trailing text");
    return j;
  }

 private:
  [[noreturn]] void fail(const std::string& why) {
    throw std::runtime_error("JSON: " + why + " at offset " + std::to_string(i_));
  }
  void blanks() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\n' || t_[i_] == '\r' || t_[i_] == '\t')) ++i_;
  }
  bool eat(char c) {
    blanks();
    if (i_ < t_.size() && t_[i_] == c) { ++i_; return true; }
    return false;
  }
  void expect(char c) { if (!eat(c)) fail(std::string("expected '") + c + "'"); }
  bool word(const char* w) {
    const std::string s(w);
    if (t_.compare(i_, s.size(), s) == 0) { i_ += s.size(); return true; }
    return false;
  }
  std::string string_body() {
    expect('"');
    std::string s;
    while (i_ < t_.size() && t_[i_] != '"') {
      if (static_cast<unsigned char>(t_[i_]) < 0x20) fail("control character in string");
      if (t_[i_] == '\\') {
        ++i_;
        if (i_ >= t_.size()) fail("bad escape");
        const char e = t_[i_];
        if (e == 'u') { s += '?'; i_ += 4; }
        else if (std::string("\"\\/bfnrt").find(e) == std::string::npos) fail("bad escape");
        else s += e;
        ++i_;
      } else {
        s += t_[i_++];
      }
    }
    if (i_ >= t_.size()) fail("unterminated string");
    ++i_;
    return s;
  }
  Json value() {
    blanks();
    Json j;
    if (i_ >= t_.size()) fail("unexpected end");
    const char c = t_[i_];
    if (c == '{') {
      ++i_;
      j.kind = Json::object;
      if (eat('}')) return j;
      do {
        blanks();
        const std::string key = string_body();
        expect(':');
        if (!j.fields.emplace(key, value()).second) fail("duplicate key " + key);
      } while (eat(','));
      expect('}');
    } else if (c == '[') {
      ++i_;
      j.kind = Json::array;
      if (eat(']')) return j;
      do j.items.push_back(value()); while (eat(','));
      expect(']');
    } else if (c == '"') {
      j.kind = Json::string;
      j.text = string_body();
    } else if (word("true")) {
      j.kind = Json::boolean;
      j.flag = true;
    } else if (word("false")) {
      j.kind = Json::boolean;
    } else if (word("null")) {
      j.kind = Json::null;
    } else {
      // JSON number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
      const std::size_t start = i_;
      if (t_[i_] == '-') ++i_;
      auto digits = [&] {
        const std::size_t from = i_;
        while (i_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_]))) ++i_;
        return i_ - from;
      };
      if (i_ < t_.size() && t_[i_] == '0') ++i_;
      else if (digits() == 0) fail("bad value");
      if (i_ < t_.size() && t_[i_] == '.') { ++i_; if (digits() == 0) fail("bad fraction"); }
      if (i_ < t_.size() && (t_[i_] == 'e' || t_[i_] == 'E')) {
        ++i_;
        if (i_ < t_.size() && (t_[i_] == '+' || t_[i_] == '-')) ++i_;
        if (digits() == 0) fail("bad exponent");
      }
      j.kind = Json::number;
      j.value = std::stod(t_.substr(start, i_ - start));
    }
    return j;
  }
  const std::string& t_;
  std::size_t i_ = 0;
};

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, separator)) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.push_back("");
  return fields;
}

/// Comparisons of a few operations on the core (the writers' input).
std::vector<Comparison> sample_comparisons(const Config& config) {
  const Core core(config);
  const Scoreboard scoreboard(config);
  std::vector<Comparison> out;
  const Formats& f = core.formats();
  for (const auto& [cos, n, r, g, b] : std::vector<std::tuple<double, long long, long long, long long, long long>>{
           {0.9, 10, 200, 100, 50}, {1.0, 1, 255, 255, 255}, {0.0, 1000, 0, 1, 2}, {0.5, 3, 7, 8, 9}}) {
    Stimulus s = make_stimulus(f, cos, n, {r, g, b}, "");
    out.push_back(scoreboard.compare(s, core.run(s.operands), 2.5));
  }
  return out;
}

std::string write_all(OutputFormat format, const Config& config, std::string* side_text = nullptr) {
  std::ostringstream out, side;
  auto report = make_report(format, out, side);
  RunDescription run;
  run.model = "core";
  run.stimulus = "test \"quoted\"";
  run.config = config;
  run.clock_period_ps = 10000;
  const auto comparisons = sample_comparisons(config);
  run.operations = comparisons.size();
  Scoreboard scoreboard(config);
  report->begin(run);
  for (const Comparison& c : comparisons) {
    scoreboard.record(c);
    report->row(c);
  }
  report->end(scoreboard.summary(), 0.5);
  if (side_text) *side_text = side.str();
  return out.str();
}

const std::vector<std::string> expected_fields = {
    "cos", "n", "r", "g", "b", "cos_q", "approx", "approx_ref", "norm", "norm_ref",
    "norm_exact", "out_r", "out_g", "out_b", "out_r_ref", "out_g_ref", "out_b_ref", "cycles",
    "reg1_hex", "reg9_pass1_hex", "reg9_pass2_hex", "pin24_hex", "pin25_hex", "pin26_hex", "pass"};

}  // namespace

TEST(TbReport, HexCodesAtBusWidthTwosComplement) {
  EXPECT_EQ(hex_code(0, 17), "0x00000");
  EXPECT_EQ(hex_code(65536, 17), "0x10000");     // cos = 1.0 in U1.16
  EXPECT_EQ(hex_code(-1, 37), "0x1fffffffff");   // −1 LSB in S14.22 (37 bits)
  EXPECT_EQ(hex_code(-1, 32), "0xffffffff");     // −1 LSB on pins 24–26 (S18.13)
  EXPECT_EQ(hex_code(-(std::int64_t{1} << 31), 32), "0x80000000");
  EXPECT_EQ(hex_code(0x2a, 8), "0x2a");
}

TEST(TbReport, CsvHeaderAndRows) {
  std::string side;
  const std::string text = write_all(OutputFormat::csv, Config{}, &side);
  std::istringstream in(text);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(split(line, ','), expected_fields);
  const Formats f{};
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    const auto fields = split(line, ',');
    ASSERT_EQ(fields.size(), expected_fields.size()) << line;
    // Hex fields carry ceil(width/4) digits: reg1 17 bits, reg9 37 bits, pins 32 bits.
    EXPECT_EQ(fields[18].size(), 2u + (f.cos.width() + 3) / 4);
    EXPECT_EQ(fields[19].size(), 2u + (f.reg9.width() + 3) / 4);
    EXPECT_EQ(fields[20].size(), 2u + (f.reg9.width() + 3) / 4);
    for (int i = 21; i <= 23; ++i) EXPECT_EQ(fields[i].size(), 2u + (f.out.width() + 3) / 4);
    // The hex code of register 1 and cos_q are the same number.
    EXPECT_DOUBLE_EQ(std::stod(fields[5]),
                     std::ldexp(static_cast<double>(std::stoll(fields[18], nullptr, 16)), -16));
    EXPECT_EQ(fields[24], "1");
    ++rows;
  }
  EXPECT_EQ(rows, 4u);
  // The summary goes beside the CSV (standard error), never into it.
  EXPECT_NE(side.find("summary: 4 computation(s)"), std::string::npos);
  EXPECT_EQ(text.find("summary"), std::string::npos);
}

TEST(TbReport, JsonParsesWithSettingsResultsAndSummary) {
  const std::string text = write_all(OutputFormat::json, Config{});
  Json doc;
  ASSERT_NO_THROW(doc = JsonParser(text).parse()) << text;
  ASSERT_EQ(doc.kind, Json::object);
  EXPECT_EQ(doc["tool"].text, "specular_tb");
  EXPECT_EQ(doc["settings"]["model"].text, "core");
  EXPECT_EQ(doc["settings"]["stimulus"].text, "test \"quoted\"");
  EXPECT_EQ(doc["settings"]["normalisation"].text, "patent");
  EXPECT_EQ(doc["settings"]["formats"]["reg9"].text, "S14.22");
  const Json& results = doc["results"];
  ASSERT_EQ(results.kind, Json::array);
  ASSERT_EQ(results.items.size(), 4u);
  for (const Json& r : results.items) {
    ASSERT_EQ(r.kind, Json::object);
    EXPECT_EQ(r.fields.size(), expected_fields.size());
    for (const std::string& key : expected_fields) EXPECT_TRUE(r.fields.count(key)) << key;
    EXPECT_EQ(r["reg9_pass2_hex"].text.size(), 2u + 10u);
    EXPECT_EQ(r["pass"].kind, Json::boolean);
  }
  // First row: cos 0.9, n 10 → register 1 holds round(0.9·2^16)/2^16.
  const Json& first = results.items[0];
  EXPECT_EQ(first["n"].value, 10);
  EXPECT_DOUBLE_EQ(first["cos_q"].value, std::round(0.9 * 65536) / 65536);
  const double cos_q = first["cos_q"].value;
  const double a = 1 - 0.5 * std::log2(1 - 10 * std::log2(cos_q));
  EXPECT_DOUBLE_EQ(first["approx_ref"].value, a);
  EXPECT_NEAR(first["approx"].value, a, std::ldexp(1.0, -10));
  EXPECT_DOUBLE_EQ(first["norm_exact"].value, 2 * M_PI / 12 * std::pow(cos_q, 10));
  const Json& summary = doc["summary"];
  EXPECT_EQ(summary["count"].value, 4);
  EXPECT_EQ(summary["failures"].value, 0);
  EXPECT_TRUE(summary["pass"].flag);
  EXPECT_EQ(summary["max_norm_error"].kind, Json::object);
  EXPECT_EQ(summary["cycles_max"].value, 2.5);
}

// JSON Lines (issue 27): each line a document of its own; the rows can be read after
// a flush (a batch), before the summary exists; the same objects as the JSON's.
TEST(TbReport, JsonLinesReadableBeforeTheEnd) {
  std::ostringstream out, side;
  auto report = make_report(OutputFormat::jsonl, out, side);
  RunDescription run;
  run.model = "core";
  run.stimulus = "test \"quoted\"";
  const auto comparisons = sample_comparisons(Config{});
  Scoreboard scoreboard(Config{});
  report->begin(run);
  for (const Comparison& c : comparisons) {
    scoreboard.record(c);
    report->row(c);
  }
  report->flush();
  const auto lines_of = [](const std::string& text) {
    std::vector<Json> docs;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) docs.push_back(JsonParser(line).parse());
    return docs;
  };
  std::vector<Json> before;
  ASSERT_NO_THROW(before = lines_of(out.str())) << out.str();
  ASSERT_EQ(before.size(), 1 + comparisons.size());
  EXPECT_EQ(before[0]["tool"].text, "specular_tb");
  EXPECT_EQ(before[0]["settings"]["stimulus"].text, "test \"quoted\"");
  EXPECT_EQ(before[1]["n"].value, 10);
  report->end(scoreboard.summary(), 0);
  std::vector<Json> after;
  ASSERT_NO_THROW(after = lines_of(out.str())) << out.str();
  ASSERT_EQ(after.size(), 2 + comparisons.size());
  EXPECT_EQ(after.back()["summary"]["count"].value, 4);
  // The rows are the JSON report's "results", field by field.
  const Json doc = JsonParser(write_all(OutputFormat::json, Config{})).parse();
  for (std::size_t i = 0; i < comparisons.size(); ++i)
    for (const std::string& key : expected_fields) {
      const Json& mine = after[1 + i][key];
      const Json& theirs = doc["results"].items[i][key];
      EXPECT_EQ(mine.kind, theirs.kind) << key;
      EXPECT_EQ(mine.value, theirs.value) << key;
      EXPECT_EQ(mine.text, theirs.text) << key;
    }
}

TEST(TbReport, JsonWithNoResultsIsStillValid) {
  std::ostringstream out, side;
  auto report = make_report(OutputFormat::json, out, side);
  RunDescription run;
  run.model = "pin";
  report->begin(run);
  report->end(Summary{}, 0);
  Json doc;
  ASSERT_NO_THROW(doc = JsonParser(out.str()).parse()) << out.str();
  EXPECT_TRUE(doc["results"].items.empty());
  EXPECT_FALSE(doc["summary"]["pass"].flag);
}

TEST(TbReport, TextHasTableAndSummary) {
  const std::string text = write_all(OutputFormat::text, Config{});
  EXPECT_NE(text.find("approx_ref"), std::string::npos);
  EXPECT_NE(text.find("summary: 4 computation(s), 0 out of tolerance: PASS"), std::string::npos);
  EXPECT_NE(text.find("max |norm - norm_ref|"), std::string::npos);
  EXPECT_NE(text.find("max |norm - norm_exact|"), std::string::npos);
  EXPECT_NE(text.find("annotated"), std::string::npos);  // core model: cycles not measured
}
