#include "error_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>

#include "csv.h"
#include "lobes.h"
#include "parallel.h"
#include "specular/reference.h"

namespace specular {
namespace study {

namespace {

constexpr double degrees = 57.295779513082320876798154814105;

Config device_config(const Widths& widths, Saturation saturation,
                     Constants constants = Constants::patent) {
  Config config;
  config.widths = widths;
  config.saturation = saturation;
  config.constants = constants;
  config.normalisation = Normalisation::none;  // the study reads A, ahead of ROM 38
  return config;
}

// λ samples for the error curves: quadratic in i, so that the narrow lobes of large
// n get as many points as the wide ones; snapped to distinct cos codes (largest first).
std::vector<code_t> curve_codes(const Formats& formats, int samples) {
  std::vector<code_t> codes;
  for (int i = 0; i <= samples; ++i) {
    const double s = static_cast<double>(i) / samples;
    const code_t code = quantise_cos(formats, std::cos(90.0 * s * s / degrees));
    if (codes.empty() || code != codes.back()) codes.push_back(code);
  }
  return codes;
}

// λ columns of the error maps: log-spaced from 0.1° to 90°, so that every n's lobe
// (its width falls as 1/√n) spans a similar number of columns.
std::vector<double> heatmap_lambdas(int columns) {
  std::vector<double> lambdas;
  for (int j = 0; j < columns; ++j)
    lambdas.push_back(0.1 * std::pow(900.0, static_cast<double>(j) / (columns - 1)));
  return lambdas;
}

struct HeatMap {
  const char* name;
  Method method;
  bool against_formula;  // false: method − exact; true: method − formula (clamp)
};
constexpr std::array<HeatMap, 4> heatmaps = {{
    {"device_clamp", Method::device_clamp, false},
    {"schlick", Method::schlick, false},
    {"us5739820", Method::us5739820, false},
    {"device_vs_formula", Method::device_clamp, true},
}};

struct PerN {
  unsigned n = 0;
  double zero_device = 0;
  std::array<MaxError, method_count> max{};
  MaxError device_vs_formula;
  MaxError literal_vs_formula;
};

}  // namespace

const char* method_name(Method method) {
  switch (method) {
    case Method::device_clamp: return "device_clamp";
    case Method::device_literal: return "device_literal";
    case Method::formula_clamp: return "formula_clamp";
    case Method::formula_literal: return "formula_literal";
    case Method::schlick: return "schlick";
    case Method::us5739820: return "us5739820";
    case Method::device_minimax_half: return "device_minimax_half";
    case Method::device_minimax: return "device_minimax";
  }
  return "?";
}

MaxError max_abs_difference(const std::vector<double>& f, const std::vector<double>& g,
                            const std::vector<double>& cos) {
  MaxError worst;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double d = std::abs(f[i] - g[i]);
    if (d > worst.value) worst = {d, cos[i]};
  }
  return worst;
}

LobeEvaluator::LobeEvaluator(const Widths& widths)
    : clamp_(device_config(widths, Saturation::clamp)),
      literal_(device_config(widths, Saturation::literal)),
      minimax_half_(device_config(widths, Saturation::clamp, Constants::minimax_half)),
      minimax_(device_config(widths, Saturation::clamp, Constants::minimax)) {}

LobeTables LobeEvaluator::tables(unsigned n) const {
  const Formats& f = clamp_.formats();
  const std::size_t codes = static_cast<std::size_t>(f.cos.one()) + 1;
  LobeTables t;
  t.n = n;
  t.cos.resize(codes);
  t.exact.resize(codes);
  for (auto& v : t.values) v.resize(codes);
  const auto set = [&t](Method m, std::size_t c, double v) {
    t.values[static_cast<std::size_t>(m)][c] = v;
  };
  t.values[static_cast<std::size_t>(Method::device_clamp)] =
      device_table(clamp_, n, DeviceValue::approx);
  t.values[static_cast<std::size_t>(Method::device_literal)] =
      device_table(literal_, n, DeviceValue::approx);
  // s·A: what multiplier 39 gives with K = 1, the device's own approximation of cos^n.
  t.values[static_cast<std::size_t>(Method::device_minimax_half)] =
      device_table(minimax_half_, n, DeviceValue::normalised);
  t.values[static_cast<std::size_t>(Method::device_minimax)] =
      device_table(minimax_, n, DeviceValue::normalised);
  const int bits = f.cos.frac_bits;
  for (std::size_t c = 0; c < codes; ++c) {
    const double cos = f.cos.to_real(static_cast<code_t>(c));
    t.cos[c] = cos;
    t.exact[c] = reference::exact_lobe(cos, n);
    const double literal = reference::approx(cos, n, Saturation::literal, bits);
    set(Method::formula_literal, c, literal);
    set(Method::formula_clamp, c, reference::approx(cos, n, Saturation::clamp, bits));
    set(Method::schlick, c, schlick(cos, n));
    set(Method::us5739820, c, us5739820(cos, n));
  }
  return t;
}

double device_zero_crossing(const LobeTables& tables) {
  const std::vector<double>& literal = tables.of(Method::device_literal);
  std::size_t first = literal.size();
  while (first > 0 && literal[first - 1] >= 0) --first;  // walk down while non-negative
  return first < literal.size() ? tables.cos[first] : 1.0;
}

ErrorSummary run_error_study(const StudyOptions& options) {
  const LobeEvaluator evaluator;
  const Formats& formats = evaluator.device(Saturation::clamp).formats();
  const std::vector<unsigned> ns = options.n_values();
  const std::vector<code_t> codes = curve_codes(formats, options.quick ? 200 : 1500);
  const std::vector<double> lambdas = heatmap_lambdas(options.quick ? 32 : 256);
  std::vector<code_t> lambda_codes;
  for (double lambda : lambdas) lambda_codes.push_back(quantise_cos(formats, std::cos(lambda / degrees)));

  std::vector<PerN> per_n(ns.size());
  std::array<std::vector<std::vector<double>>, heatmaps.size()> maps;
  for (auto& map : maps) map.assign(ns.size(), std::vector<double>(lambdas.size()));
  std::map<unsigned, std::vector<std::vector<double>>> curve_rows;
  std::mutex curves_lock;
  const std::vector<unsigned> curve_ns = StudyOptions::curve_n_values();

  parallel_for("error study (all methods, every cos code)", ns.size(), options.workers,
               options.quiet, [&](std::size_t item, unsigned) {
    const unsigned n = ns[item];
    const LobeTables t = evaluator.tables(n);
    PerN& row = per_n[item];
    row.n = n;
    row.zero_device = device_zero_crossing(t);
    for (Method m : all_methods)
      row.max[static_cast<std::size_t>(m)] = max_abs_difference(t.of(m), t.exact, t.cos);
    row.device_vs_formula =
        max_abs_difference(t.of(Method::device_clamp), t.of(Method::formula_clamp), t.cos);
    row.literal_vs_formula =
        max_abs_difference(t.of(Method::device_literal), t.of(Method::formula_literal), t.cos);

    for (std::size_t h = 0; h < heatmaps.size(); ++h) {
      const std::vector<double>& f = t.of(heatmaps[h].method);
      const std::vector<double>& g =
          heatmaps[h].against_formula ? t.of(Method::formula_clamp) : t.exact;
      for (std::size_t j = 0; j < lambda_codes.size(); ++j) {
        const auto c = static_cast<std::size_t>(lambda_codes[j]);
        maps[h][item][j] = f[c] - g[c];
      }
    }

    if (std::find(curve_ns.begin(), curve_ns.end(), n) != curve_ns.end()) {
      std::vector<std::vector<double>> rows;
      for (code_t code : codes) {
        const auto c = static_cast<std::size_t>(code);
        std::vector<double> r = {std::acos(t.cos[c]) * degrees, t.cos[c], t.exact[c]};
        for (Method m : all_methods) r.push_back(t.of(m)[c]);
        for (Method m : all_methods) r.push_back(t.of(m)[c] - t.exact[c]);
        rows.push_back(std::move(r));
      }
      std::lock_guard<std::mutex> lock(curves_lock);
      curve_rows[n] = std::move(rows);
    }
  });

  // error_curves.csv: one row per (n, cos code); λ is the angle of the code's value.
  {
    std::vector<std::string> columns = {"n", "lambda_deg", "cos", "exact"};
    for (Method m : all_methods) columns.push_back(method_name(m));
    for (Method m : all_methods) columns.push_back(std::string(method_name(m)) + "_err");
    CsvWriter csv(options.out_dir + "/error_curves.csv", columns);
    for (const auto& [n, rows] : curve_rows)
      for (const auto& r : rows) {
        csv.cell(static_cast<long long>(n));
        for (double v : r) csv.cell(v);
        csv.end_row();
      }
  }

  // max_error_by_n.csv, and the summary over all n.
  ErrorSummary summary;
  {
    std::vector<std::string> columns = {"n", "zero_cos_formula", "zero_cos_device"};
    for (Method m : all_methods) {
      columns.push_back(std::string(method_name(m)) + "_max_err");
      columns.push_back(std::string(method_name(m)) + "_at_cos");
    }
    for (const char* c : {"device_vs_formula_clamp_max", "device_vs_formula_clamp_at_cos",
                          "device_vs_formula_literal_max", "device_vs_formula_literal_at_cos"})
      columns.push_back(c);
    CsvWriter csv(options.out_dir + "/max_error_by_n.csv", columns);
    for (const PerN& row : per_n) {
      csv.cell(static_cast<long long>(row.n)).cell(formula_zero_crossing(row.n)).cell(row.zero_device);
      for (std::size_t m = 0; m < method_count; ++m) {
        csv.cell(row.max[m].value).cell(row.max[m].at_cos);
        if (row.max[m].value > summary.worst[m].value)
          summary.worst[m] = {row.max[m].value, row.n, row.max[m].at_cos};
      }
      csv.cell(row.device_vs_formula.value).cell(row.device_vs_formula.at_cos);
      csv.cell(row.literal_vs_formula.value).cell(row.literal_vs_formula.at_cos);
      csv.end_row();
      if (row.device_vs_formula.value > summary.device_vs_formula.value)
        summary.device_vs_formula = {row.device_vs_formula.value, row.n, row.device_vs_formula.at_cos};
    }
  }

  // heatmap_<name>.csv: rows n, columns λ in degrees (the header holds the λ values).
  for (std::size_t h = 0; h < heatmaps.size(); ++h) {
    std::vector<std::string> columns = {"n"};
    for (double lambda : lambdas) {
      char text[32];
      std::snprintf(text, sizeof text, "%.6g", lambda);
      columns.push_back(text);
    }
    CsvWriter csv(options.out_dir + "/heatmap_" + heatmaps[h].name + ".csv", columns);
    for (std::size_t i = 0; i < ns.size(); ++i) {
      csv.cell(static_cast<long long>(ns[i]));
      for (double v : maps[h][i]) csv.cell(v);
      csv.end_row();
    }
  }
  return summary;
}

}  // namespace study
}  // namespace specular
