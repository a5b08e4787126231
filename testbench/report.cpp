#include "report.h"

#include <charconv>
#include <cmath>
#include <iterator>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <sstream>

#include "json_report.h"  // issue 25: settings and summary objects
#include "run_models.h"
#include "usage_error.h"

namespace specular {
namespace tb {

const char* to_string(OutputFormat format) {
  switch (format) {
    case OutputFormat::text: return "text";
    case OutputFormat::csv: return "csv";
    case OutputFormat::json: return "json";
    case OutputFormat::jsonl: return "jsonl";
  }
  return "?";
}

OutputFormat parse_output_format(const std::string& text) {
  if (text == "text") return OutputFormat::text;
  if (text == "csv") return OutputFormat::csv;
  if (text == "json") return OutputFormat::json;
  if (text == "jsonl") return OutputFormat::jsonl;
  throw UsageError("--format = '" + text + "' is not one of: text, csv, json, jsonl");
}

std::string hex_code(code_t code, int width) {
  const std::uint64_t mask = width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
  const std::uint64_t bits = static_cast<std::uint64_t>(code) & mask;
  const int digits = (width + 3) / 4;
  char buffer[24];
  std::snprintf(buffer, sizeof buffer, "0x%0*llx", digits, static_cast<unsigned long long>(bits));
  return buffer;
}

const char* csv_header() {
  return "cos,n,r,g,b,cos_q,approx,approx_ref,norm,norm_ref,norm_exact,"
         "out_r,out_g,out_b,out_r_ref,out_g_ref,out_b_ref,cycles,"
         "reg1_hex,reg9_pass1_hex,reg9_pass2_hex,pin24_hex,pin25_hex,pin26_hex,pass";
}

namespace {

/// Rows are formatted into a block of memory and written to the stream a block at a
/// time: an ostream insertion per field held the CSV at about 0.3 M rows per second,
/// three times slower than the core model computed them (docs/performance.md).
class RowBuffer {
 public:
  explicit RowBuffer(std::ostream& out) : out_(out), data_(new char[capacity]), end_(data_.get()) {}
  /// Room for one more row (a row is well under `row_max` bytes).
  void reserve_row() {
    if (static_cast<std::size_t>(end_ - data_.get()) > capacity - row_max) write();
  }
  void text(const char* text, std::size_t size) {
    std::memcpy(end_, text, size);
    end_ += size;
  }
  template <std::size_t N>
  void literal(const char (&chars)[N]) { text(chars, N - 1); }
  void put(char ch) { *end_++ = ch; }
  void real(double value) {
    // std::to_chars's shortest form costs about 50 ns; an integer below 10^5 (most of
    // a run's zeros) reads the same in its shortest form ("-0" for -0.0 excepted). The
    // range first: a double outside int's (1e300, a NaN) converted to int is undefined
    // behaviour (clang's UBSan, float-cast-overflow, which gcc's leaves out).
    if (value > -1e5 && value < 1e5 && value == static_cast<double>(static_cast<int>(value)) &&
        !(value == 0 && std::signbit(value))) {
      const int whole = static_cast<int>(value);
      if (whole < 0) *end_++ = '-';
      integer(static_cast<unsigned long long>(whole < 0 ? -whole : whole));
    } else {
      end_ = std::to_chars(end_, end_ + 32, value).ptr;
    }
  }
  /// A column's last value and its text: a sweep repeats cos, cos_q and cycles row
  /// after row, and many other values from one row to the next.
  struct Column {
    std::uint64_t bits = 0;
    bool valid = false;
    unsigned char size = 0;
    char text[32];
  };
  void real(double value, Column& column) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    if (!column.valid || bits != column.bits) {
      char* const begin = end_;
      real(value);
      column.size = static_cast<unsigned char>(end_ - begin);
      std::memcpy(column.text, begin, column.size);
      column.bits = bits;
      column.valid = true;
    } else {
      text(column.text, column.size);
    }
  }
  void integer(unsigned long long value) { end_ = std::to_chars(end_, end_ + 24, value).ptr; }
  /// hex_code(code, width), without a string.
  void hex(code_t code, int width) {
    const std::uint64_t mask = width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
    std::uint64_t bits = static_cast<std::uint64_t>(code) & mask;
    int digits = (width + 3) / 4;
    char buffer[24];
    char* p = buffer + sizeof buffer;
    do {
      *--p = "0123456789abcdef"[bits & 15];
      bits >>= 4;
    } while (bits != 0);
    const int written = static_cast<int>(buffer + sizeof buffer - p);
    *end_++ = '0';
    *end_++ = 'x';
    for (; digits > written; --digits) *end_++ = '0';
    text(p, static_cast<std::size_t>(written));
  }
  /// Hands what is buffered to the stream.
  void write() {
    out_.write(data_.get(), end_ - data_.get());
    end_ = data_.get();
  }

 private:
  static constexpr std::size_t capacity = 1 << 18, row_max = 2048;
  std::ostream& out_;
  std::unique_ptr<char[]> data_;
  char* end_;
};

std::string clock_text(std::uint64_t ps) {
  std::ostringstream s;
  if (ps % 1000000 == 0) s << ps / 1000000 << " us";
  else if (ps % 1000 == 0) s << ps / 1000 << " ns";
  else s << ps << " ps";
  return s.str();
}

std::string header_line(const RunDescription& run) {
  std::ostringstream s;
  s << "model " << run.model << ", normalisation " << to_string(run.config.normalisation)
    << ", saturation " << to_string(run.config.saturation) << ", constants "
    << to_string(run.config.constants);
  if (run.model == "pin" || run.model == "rtl" || run.model == "rtl-sync") s << ", clock " << clock_text(run.clock_period_ps);
  s << ", " << run.operations << " computation(s) from " << run.stimulus;
  return s.str();
}

std::string formats_line(const Config& config) {
  const Formats f(config.widths);
  std::ostringstream s;
  s << "formats: cos " << f.cos.name() << ", reg9 " << f.reg9.name() << ", ROM 38 "
    << f.rom38.name() << ", norm " << f.norm.name() << ", out " << f.out.name();
  if (config.constants != Constants::patent) {
    // What the columns mean when pins 19 and 20 do not carry ½ and 1 (issue 14).
    const ConstantValues& c = constant_values(config.constants);
    char text[320];
    std::snprintf(text, sizeof text,
                  "\nconstants: pin 20 a = %.9f, pin 19 h = %.9f, ROM 38 scale s = %.9f; approx = "
                  "register 9 = a - h*log2(a - n*log2 cos), peak 1/s = %.6f; norm = s*K(n)*approx",
                  c.a(), c.h(), c.s(), 1.0 / c.s());
    s << text;
  }
  return s.str();
}

/// The integer codes of one computation at their buses' widths.
struct HexCodes {
  std::string reg1, reg9_pass1, reg9_pass2, pins[3];
  HexCodes(const Result& r, const Formats& f)
      : reg1(hex_code(r.reg1, f.cos.width())),
        reg9_pass1(hex_code(r.reg9_pass1, f.reg9.width())),
        reg9_pass2(hex_code(r.reg9_pass2, f.reg9.width())),
        pins{hex_code(r.out[0], f.out.width()), hex_code(r.out[1], f.out.width()),
             hex_code(r.out[2], f.out.width())} {}
};

// ---- text --------------------------------------------------------------------
class TextReport : public Report {
 public:
  explicit TextReport(std::ostream& out) : out_(out) {}
  void begin(const RunDescription& run) override {
    run_ = run;
    formats_ = std::make_unique<Formats>(run.config.widths);
    out_ << "specular_tb: " << header_line(run) << '\n' << formats_line(run.config) << "\n\n";
    if (run.text_rows) {
      char line[256];
      std::snprintf(line, sizeof line,
                    "%-10s %4s %3s %3s %3s  %-10s %-10s %-10s %-11s %-11s %-11s %-11s %-11s "
                    "%-11s %6s  %s\n",
                    "cos", "n", "R", "G", "B", "cos_q", "approx", "approx_ref", "norm",
                    "norm_ref", "norm_exact", "out_r", "out_g", "out_b", "cycles", "check");
      out_ << line;
    }
  }
  void row(const Comparison& c) override {
    if (!run_.text_rows) return;
    char line[320];
    std::snprintf(line, sizeof line,
                  "%-10.6g %4u %3u %3u %3u  %-10.8f %-10.7f %-10.7f %-11.7f %-11.7f %-11.7f "
                  "%-11.4f %-11.4f %-11.4f %6.2f  %s\n",
                  c.stimulus.cos, c.stimulus.n, c.stimulus.rgb[0], c.stimulus.rgb[1],
                  c.stimulus.rgb[2], c.ref.cos_q, c.approx, c.ref.approx_ref, c.norm,
                  c.ref.norm_ref, c.ref.norm_exact, c.out[0], c.out[1], c.out[2], c.cycles,
                  verdict(c).c_str());
    out_ << line;
  }
  void end(const Summary& summary, double seconds) override {
    if (!run_.text_rows)
      out_ << "(one row per computation: use --format csv or json)\n";
    out_ << '\n';
    write_summary_text(out_, summary, run_, seconds);
  }

 private:
  static std::string verdict(const Comparison& c) {
    if (c.pass()) return "ok";
    std::string s = "FAIL:";
    if (!c.approx_ok) s += " approx";
    if (!c.norm_ok) s += " norm";
    if (!c.out_ok) s += " out";
    if (!c.cycles_ok) s += " cycles";
    return s;
  }
  std::ostream& out_;
  RunDescription run_;
  std::unique_ptr<Formats> formats_;
};

// ---- CSV ---------------------------------------------------------------------
class CsvReport : public Report {
 public:
  CsvReport(std::ostream& out, std::ostream& side) : out_(out), side_(side) {}
  void begin(const RunDescription& run) override {
    run_ = run;
    formats_ = std::make_unique<Formats>(run.config.widths);
    out_ << csv_header() << '\n';
  }
  void row(const Comparison& c) override {
    const Formats& f = *formats_;
    RowBuffer& b = buffer_;
    b.reserve_row();
    b.real(c.stimulus.cos, columns_[0]);
    for (unsigned v : {c.stimulus.n, c.stimulus.rgb[0], c.stimulus.rgb[1], c.stimulus.rgb[2]}) {
      b.put(',');
      b.integer(v);
    }
    const double reals[] = {c.ref.cos_q, c.approx, c.ref.approx_ref, c.norm, c.ref.norm_ref,
                            c.ref.norm_exact, c.out[0], c.out[1], c.out[2], c.ref.out_ref[0],
                            c.ref.out_ref[1], c.ref.out_ref[2], c.cycles};
    for (std::size_t i = 0; i < std::size(reals); ++i) {
      b.put(',');
      b.real(reals[i], columns_[i + 1]);
    }
    const std::pair<code_t, int> codes[] = {
        {c.result.reg1, f.cos.width()},      {c.result.reg9_pass1, f.reg9.width()},
        {c.result.reg9_pass2, f.reg9.width()}, {c.result.out[0], f.out.width()},
        {c.result.out[1], f.out.width()},    {c.result.out[2], f.out.width()}};
    for (const auto& [code, width] : codes) {
      b.put(',');
      b.hex(code, width);
    }
    b.put(',');
    b.put(c.pass() ? '1' : '0');
    b.put('\n');
  }
  void flush() override {
    buffer_.write();
    out_.flush();
  }
  void end(const Summary& summary, double seconds) override {
    buffer_.write();
    write_summary_text(side_, summary, run_, seconds);
  }

 private:
  std::ostream& out_;
  RowBuffer buffer_{out_};
  RowBuffer::Column columns_[14];
  std::ostream& side_;
  RunDescription run_;
  std::unique_ptr<Formats> formats_;
};

// ---- JSON --------------------------------------------------------------------
class JsonReport : public Report {
 public:
  explicit JsonReport(std::ostream& out) : out_(out) {}
  void begin(const RunDescription& run) override {
    formats_ = std::make_unique<Formats>(run.config.widths);
    // issue 25: settings and summary through nlohmann-json (json_report.h), the objects
    // a merge of sharded runs writes too; rows stay on the buffered writer.
    out_ << "{\n  \"tool\": \"specular_tb\",\n  \"settings\": " << dump_json(settings_json(run))
         << ",\n  \"results\": [";
  }
  void row(const Comparison& c) override {
    const Formats& f = *formats_;
    RowBuffer& b = buffer_;
    b.reserve_row();
    if (first_) b.literal("\n    {\"cos\": ");
    else b.literal(",\n    {\"cos\": ");
    first_ = false;
    b.real(c.stimulus.cos, columns_[0]);
    b.literal(", \"n\": ");
    b.integer(c.stimulus.n);
    b.literal(", \"r\": ");
    b.integer(c.stimulus.rgb[0]);
    b.literal(", \"g\": ");
    b.integer(c.stimulus.rgb[1]);
    b.literal(", \"b\": ");
    b.integer(c.stimulus.rgb[2]);
    struct Field {
      const char* key;  // with its quotes, colon and the comma before
      std::size_t size;
      double value;
    };
#define SPECULAR_FIELD(name, value) {", \"" name "\": ", sizeof(", \"" name "\": ") - 1, value}
    const Field reals[] = {
        SPECULAR_FIELD("cos_q", c.ref.cos_q),         SPECULAR_FIELD("approx", c.approx),
        SPECULAR_FIELD("approx_ref", c.ref.approx_ref), SPECULAR_FIELD("norm", c.norm),
        SPECULAR_FIELD("norm_ref", c.ref.norm_ref),   SPECULAR_FIELD("norm_exact", c.ref.norm_exact),
        SPECULAR_FIELD("out_r", c.out[0]),            SPECULAR_FIELD("out_g", c.out[1]),
        SPECULAR_FIELD("out_b", c.out[2]),            SPECULAR_FIELD("out_r_ref", c.ref.out_ref[0]),
        SPECULAR_FIELD("out_g_ref", c.ref.out_ref[1]), SPECULAR_FIELD("out_b_ref", c.ref.out_ref[2]),
        SPECULAR_FIELD("cycles", c.cycles)};
#undef SPECULAR_FIELD
    for (std::size_t i = 0; i < std::size(reals); ++i) {
      b.text(reals[i].key, reals[i].size);
      b.real(reals[i].value, columns_[i + 1]);
    }
    b.literal(", \"reg1_hex\": \"");
    b.hex(c.result.reg1, f.cos.width());
    b.literal("\", \"reg9_pass1_hex\": \"");
    b.hex(c.result.reg9_pass1, f.reg9.width());
    b.literal("\", \"reg9_pass2_hex\": \"");
    b.hex(c.result.reg9_pass2, f.reg9.width());
    b.literal("\", \"pin24_hex\": \"");
    b.hex(c.result.out[0], f.out.width());
    b.literal("\", \"pin25_hex\": \"");
    b.hex(c.result.out[1], f.out.width());
    b.literal("\", \"pin26_hex\": \"");
    b.hex(c.result.out[2], f.out.width());
    if (c.pass()) b.literal("\", \"pass\": true}");
    else b.literal("\", \"pass\": false}");
  }
  void flush() override {
    buffer_.write();
    out_.flush();
  }
  void end(const Summary& s, double) override {
    buffer_.write();
    out_ << (first_ ? "],\n" : "\n  ],\n") << "  \"summary\": " << dump_json(summary_json(s))
         << "\n}\n";
  }

 private:
  std::ostream& out_;
  RowBuffer buffer_{out_};
  RowBuffer::Column columns_[14];
  std::unique_ptr<Formats> formats_;
  bool first_ = true;
};

// ---- JSON Lines ---------------------------------------------------------------
/// The JSON report's objects one to a line, for a reader that follows the run as it
/// goes (rows reach the stream after each batch): a line {"tool", "settings"}, a line
/// per result (the objects of the JSON's "results"), a line {"summary"}. The JSON
/// writer writes into a buffer here, and its layout is folded into lines.
class JsonLinesReport : public Report {
 public:
  explicit JsonLinesReport(std::ostream& out) : out_(out) {}
  void begin(const RunDescription& run) override {
    inner_.begin(run);
    std::string text = take();
    text = text.substr(0, text.rfind(",\n  \"results\": ["));
    out_ << one_line(text) << "}\n";
  }
  void row(const Comparison& c) override { inner_.row(c); }
  void flush() override {
    inner_.flush();
    rows_out();
    out_.flush();
  }
  void end(const Summary& summary, double seconds) override {
    inner_.flush();
    rows_out();
    inner_.end(summary, seconds);
    const std::string text = take();
    out_ << '{' << one_line(text.substr(text.find("\"summary\""))) << '\n';
  }

 private:
  std::string take() {
    std::string text = capture_.str();
    capture_.str(std::string());
    return text;
  }
  /// Rows come as "\n    {...}" or ",\n    {...}": one a line.
  void rows_out() {
    const std::string text = take();
    std::size_t at = 0;
    while ((at = text.find('{', at)) != std::string::npos) {
      const std::size_t end = text.find("\n", at);
      const std::size_t stop = end == std::string::npos ? text.size() : end;
      const std::size_t close = text[stop - 1] == ',' ? stop - 1 : stop;
      out_.write(text.data() + at, static_cast<std::streamsize>(close - at));
      out_ << '\n';
      at = stop;
    }
  }
  /// Newlines and the indentation after them removed (strings hold none: escaped).
  static std::string one_line(const std::string& text) {
    std::string line;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] != '\n') {
        line += text[i];
        continue;
      }
      while (i + 1 < text.size() && text[i + 1] == ' ') ++i;
    }
    return line;
  }
  std::ostream& out_;
  std::ostringstream capture_;
  JsonReport inner_{capture_};
};

void worst_line(std::ostream& out, const char* label, const Worst& w, const char* note) {
  out << "  " << std::left << std::setw(26) << label << std::right << " = " << std::setprecision(4)
      << std::scientific << w.error << std::defaultfloat << " at cos " << std::setprecision(8)
      << w.cos_q << ", n " << w.n;
  if (note == nullptr)
    out << "  (" << std::fixed << std::setprecision(1) << 100.0 * w.tolerance_used
        << std::defaultfloat << "% of tolerance at worst)";
  else
    out << "  (" << note << ")";
  out << '\n';
}

}  // namespace

void write_summary_text(std::ostream& out, const Summary& s, const RunDescription& run,
                        double seconds) {
  const auto flags = out.flags();
  const auto precision = out.precision();
  out << "summary: " << s.count << " computation(s), " << s.failures << " out of tolerance: "
      << (s.pass() ? "PASS" : "FAIL") << '\n';
  if (s.failures > 0)
    out << "  failed checks: approx " << s.approx_failures << ", norm " << s.norm_failures
        << ", out " << s.out_failures << ", cycles " << s.cycles_failures << '\n';
  const bool variant = run.model.rfind("variant", 0) == 0;  // issue 26: report only
  if (s.count > 0 && variant) {
    worst_line(out, "max |lobe - norm_exact|", s.norm_exact, "lobe vs K(n)*cos_q^n");
    worst_line(out, "max |out - norm_exact*I|", s.out, "pins 24-26 vs K(n)*cos_q^n*I");
    worst_line(out, "max |lobe - norm_ref|", s.norm, "vs the patent's formula");
    out << "  report only: a variant passes every computation (its own bound: docs/variants/)\n";
  } else if (s.count > 0) {
    worst_line(out, "max |approx - approx_ref|", s.approx, nullptr);
    worst_line(out, "max |norm - norm_ref|", s.norm, nullptr);
    worst_line(out, "max |norm - norm_exact|", s.norm_exact,
               "the formula's own error; no tolerance");
    worst_line(out, "max |out - out_ref|", s.out, nullptr);
    out << std::setprecision(6) << "  cycles, start to pin 35 rising: " << s.cycles_min;
    if (s.cycles_max != s.cycles_min) out << " .. " << s.cycles_max;
    out << (run.model == "core"  ? " (annotated from the spec: the core model has no clock)"
            : run.model == "tlm" ? " (annotated by the TLM lt target on its START write)"
                                 : " (measured on the pins)")
        << '\n';
  }
  if (s.count > 0 && !variant) {  // issue 61: docs/energy.md
    const bool drawn = run.model == "pin" || run.model == "rtl";
    out << std::fixed << std::setprecision(1) << "  energy: " << s.energy_pj / static_cast<double>(s.count)
        << " pJ per result, " << s.energy_pj / 1000 << " nJ in all ("
        << (drawn ? "the drawn device" : "the synchronous device")
        << "'s gate-level figures: docs/energy.md)\n";
    if (s.energy_bus_pj != 0)
      out << "  TLM target's energy: " << (s.energy_pj + s.energy_bus_pj) / static_cast<double>(s.count)
          << " pJ per result, " << (s.energy_pj + s.energy_bus_pj) / 1000
          << " nJ in all (the operations, the register reads and writes, every clock)\n";
    out.flags(flags);
  }
  if (!s.failure_traces.empty()) {
    out << "  waveforms of failing operations (each with the one before it; times are the replay's):\n";
    for (const std::string& file : s.failure_traces) out << "    " << file << '\n';
  }
  if (s.failure_traces_left_out > 0)
    out << "  " << s.failure_traces_left_out
        << " more failing operation(s) not traced (--trace-failures-max)\n";
  if (!variant) out << "  tolerances: approx 2^-10; norm 2^-10*max(1,K); out 2^-10*max(1,K)*I + 1 LSB\n";
  if (seconds >= 0)
    out << "  run time " << std::fixed << std::setprecision(2) << seconds << " s\n";
  out.flags(flags);
  out.precision(precision);
}

std::unique_ptr<Report> make_report(OutputFormat format, std::ostream& out, std::ostream& side) {
  switch (format) {
    case OutputFormat::text: return std::make_unique<TextReport>(out);
    case OutputFormat::csv: return std::make_unique<CsvReport>(out, side);
    case OutputFormat::json: return std::make_unique<JsonReport>(out);
    case OutputFormat::jsonl: return std::make_unique<JsonLinesReport>(out);
  }
  return nullptr;
}

}  // namespace tb
}  // namespace specular
