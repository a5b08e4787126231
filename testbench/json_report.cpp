#include "json_report.h"

#include <cstdio>
#include <utility>

namespace specular {
namespace tb {

Json run_settings_json(const RunDescription& run) {
  Json s;
  s["model"] = run.model;
  s["stimulus"] = run.stimulus;
  s["normalisation"] = to_string(run.config.normalisation);
  s["saturation"] = to_string(run.config.saturation);
  s["constants"] = to_string(run.config.constants);
  s["clock_period_ps"] = run.clock_period_ps;
  s["operations"] = run.operations;
  return s;
}

Json settings_json(const RunDescription& run) {
  const Formats f(run.config.widths);
  Json s = run_settings_json(run);
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
  if (!s.failure_traces.empty() || s.failure_traces_left_out > 0) {  // --trace-failures
    j["failure_traces"] = s.failure_traces;
    j["failure_traces_left_out"] = s.failure_traces_left_out;
  }
  j["cycles_min"] = s.cycles_min;
  j["cycles_max"] = s.cycles_max;
  j["energy_pj"] = s.energy_pj;  // issue 61
  if (s.energy_bus_pj != 0) j["energy_bus_pj"] = s.energy_bus_pj;
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
  s.energy_pj = j.value("energy_pj", 0.0);  // absent from partial results before issue 61
  s.energy_bus_pj = j.value("energy_bus_pj", 0.0);
  const std::string checksum = j.at("checksum").get<std::string>();
  std::size_t used = 0;
  s.checksum = std::stoull(checksum, &used, 16);
  if (used != checksum.size()) throw std::invalid_argument("checksum '" + checksum + "' is not hexadecimal");
  return s;
}

}  // namespace tb
}  // namespace specular
