#include "json_report.h"

#include <cstdio>
#include <utility>

namespace specular {
namespace tb {

std::string dump_json(const Json& json) {
  return json.dump(-1, ' ', false, Json::error_handler_t::replace);
}

Json settings_json(const RunDescription& run) {
  const Formats f(run.config.widths);
  Json s;
  s["model"] = run.model;
  s["stimulus"] = run.stimulus;
  s["normalisation"] = to_string(run.config.normalisation);
  s["saturation"] = to_string(run.config.saturation);
  s["constants"] = to_string(run.config.constants);
  s["clock_period_ps"] = run.clock_period_ps;
  s["operations"] = run.operations;
  s["formats"] = Json{{"cos", f.cos.name()}, {"reg9", f.reg9.name()}, {"rom38", f.rom38.name()},
                      {"norm", f.norm.name()}, {"out", f.out.name()}};
  return s;
}

namespace {

Json worst_json(const Worst& w, bool with_tolerance, bool places) {
  Json j{{"value", w.error}, {"cos_q", w.cos_q}, {"n", w.n}};
  if (with_tolerance) j["tolerance_used"] = w.tolerance_used;
  if (places) j["at"] = w.at;
  return j;
}

Worst worst_from_json(const Json& j, bool with_tolerance) {
  Worst w;
  w.error = j.at("value").get<double>();
  w.cos_q = j.at("cos_q").get<double>();
  w.n = j.at("n").get<unsigned>();
  if (with_tolerance) w.tolerance_used = j.at("tolerance_used").get<double>();
  w.at = j.at("at").get<std::size_t>();
  return w;
}

std::string hex64(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace

Json summary_json(const Summary& s, bool places) {
  Json j;
  j["count"] = s.count;
  j["failures"] = s.failures;
  j["pass"] = s.pass();
  j["failures_by_check"] = Json{{"approx", s.approx_failures}, {"norm", s.norm_failures},
                                {"out", s.out_failures}, {"cycles", s.cycles_failures}};
  j["max_approx_error"] = worst_json(s.approx, true, places);
  j["max_norm_error"] = worst_json(s.norm, true, places);
  j["max_norm_exact_error"] = worst_json(s.norm_exact, false, places);
  j["max_out_error"] = worst_json(s.out, true, places);
  j["cycles_min"] = s.cycles_min;
  j["cycles_max"] = s.cycles_max;
  if (places) j["checksum"] = hex64(s.checksum);
  return j;
}

Summary summary_from_json(const Json& j) {
  Summary s;
  s.count = j.at("count").get<std::size_t>();
  s.failures = j.at("failures").get<std::size_t>();
  const Json& by = j.at("failures_by_check");
  s.approx_failures = by.at("approx").get<std::size_t>();
  s.norm_failures = by.at("norm").get<std::size_t>();
  s.out_failures = by.at("out").get<std::size_t>();
  s.cycles_failures = by.at("cycles").get<std::size_t>();
  s.approx = worst_from_json(j.at("max_approx_error"), true);
  s.norm = worst_from_json(j.at("max_norm_error"), true);
  s.norm_exact = worst_from_json(j.at("max_norm_exact_error"), false);
  s.out = worst_from_json(j.at("max_out_error"), true);
  s.cycles_min = j.at("cycles_min").get<double>();
  s.cycles_max = j.at("cycles_max").get<double>();
  const std::string checksum = j.at("checksum").get<std::string>();
  std::size_t used = 0;
  s.checksum = std::stoull(checksum, &used, 16);
  if (used != checksum.size()) throw std::invalid_argument("checksum '" + checksum + "' is not hexadecimal");
  return s;
}

namespace {

class JsonReport : public Report {
 public:
  explicit JsonReport(std::ostream& out) : out_(out) {}
  void begin(const RunDescription& run) override {
    formats_ = std::make_unique<Formats>(run.config.widths);
    out_ << "{\n  \"tool\": \"specular_tb\",\n  \"settings\": " << dump_json(settings_json(run))
         << ",\n  \"results\": [";
  }
  void row(const Comparison& c) override {
    const Formats& f = *formats_;
    Json j;
    j["cos"] = c.stimulus.cos;
    j["n"] = c.stimulus.n;
    j["r"] = c.stimulus.rgb[0];
    j["g"] = c.stimulus.rgb[1];
    j["b"] = c.stimulus.rgb[2];
    const std::pair<const char*, double> reals[] = {
        {"cos_q", c.ref.cos_q},       {"approx", c.approx},         {"approx_ref", c.ref.approx_ref},
        {"norm", c.norm},             {"norm_ref", c.ref.norm_ref}, {"norm_exact", c.ref.norm_exact},
        {"out_r", c.out[0]},          {"out_g", c.out[1]},          {"out_b", c.out[2]},
        {"out_r_ref", c.ref.out_ref[0]}, {"out_g_ref", c.ref.out_ref[1]},
        {"out_b_ref", c.ref.out_ref[2]}, {"cycles", c.cycles}};
    for (const auto& [key, value] : reals) j[key] = value;
    j["reg1_hex"] = hex_code(c.result.reg1, f.cos.width());
    j["reg9_pass1_hex"] = hex_code(c.result.reg9_pass1, f.reg9.width());
    j["reg9_pass2_hex"] = hex_code(c.result.reg9_pass2, f.reg9.width());
    j["pin24_hex"] = hex_code(c.result.out[0], f.out.width());
    j["pin25_hex"] = hex_code(c.result.out[1], f.out.width());
    j["pin26_hex"] = hex_code(c.result.out[2], f.out.width());
    j["pass"] = c.pass();
    out_ << (first_ ? "\n    " : ",\n    ") << dump_json(j);
    first_ = false;
  }
  void end(const Summary& s, double) override {
    out_ << (first_ ? "],\n" : "\n  ],\n") << "  \"summary\": " << dump_json(summary_json(s))
         << "\n}\n";
  }

 private:
  std::ostream& out_;
  std::unique_ptr<Formats> formats_;
  bool first_ = true;
};

}  // namespace

std::unique_ptr<Report> make_json_report(std::ostream& out) { return std::make_unique<JsonReport>(out); }

}  // namespace tb
}  // namespace specular
