#include "report.h"

#include <charconv>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include "json_report.h"
#include "run_models.h"
#include "usage_error.h"

namespace specular {
namespace tb {

const char* to_string(OutputFormat format) {
  switch (format) {
    case OutputFormat::text: return "text";
    case OutputFormat::csv: return "csv";
    case OutputFormat::json: return "json";
  }
  return "?";
}

OutputFormat parse_output_format(const std::string& text) {
  if (text == "text") return OutputFormat::text;
  if (text == "csv") return OutputFormat::csv;
  if (text == "json") return OutputFormat::json;
  throw UsageError("--format = '" + text + "' is not one of: text, csv, json");
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

/// Shortest text that reads back as the same double (CSV and JSON stay exact).
void put_real(std::ostream& out, double value) {
  char buffer[32];
  const auto done = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.write(buffer, done.ptr - buffer);
}

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
    const HexCodes hex(c.result, *formats_);
    put_real(out_, c.stimulus.cos);
    out_ << ',' << c.stimulus.n << ',' << c.stimulus.rgb[0] << ',' << c.stimulus.rgb[1] << ','
         << c.stimulus.rgb[2];
    for (double v : {c.ref.cos_q, c.approx, c.ref.approx_ref, c.norm, c.ref.norm_ref,
                     c.ref.norm_exact, c.out[0], c.out[1], c.out[2], c.ref.out_ref[0],
                     c.ref.out_ref[1], c.ref.out_ref[2], c.cycles}) {
      out_ << ',';
      put_real(out_, v);
    }
    out_ << ',' << hex.reg1 << ',' << hex.reg9_pass1 << ',' << hex.reg9_pass2 << ','
         << hex.pins[0] << ',' << hex.pins[1] << ',' << hex.pins[2] << ',' << (c.pass() ? 1 : 0)
         << '\n';
  }
  void end(const Summary& summary, double seconds) override {
    write_summary_text(side_, summary, run_, seconds);
  }

 private:
  std::ostream& out_;
  std::ostream& side_;
  RunDescription run_;
  std::unique_ptr<Formats> formats_;
};

// ---- JSON: json_report.cpp (nlohmann-json) -----------------------------------

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
  if (s.count > 0) {
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
  out << "  tolerances: approx 2^-10; norm 2^-10*max(1,K); out 2^-10*max(1,K)*I + 1 LSB\n";
  if (seconds >= 0)
    out << "  run time " << std::fixed << std::setprecision(2) << seconds << " s\n";
  out.flags(flags);
  out.precision(precision);
}

std::unique_ptr<Report> make_report(OutputFormat format, std::ostream& out, std::ostream& side) {
  switch (format) {
    case OutputFormat::text: return std::make_unique<TextReport>(out);
    case OutputFormat::csv: return std::make_unique<CsvReport>(out, side);
    case OutputFormat::json: return make_json_report(out);
  }
  return nullptr;
}

}  // namespace tb
}  // namespace specular
