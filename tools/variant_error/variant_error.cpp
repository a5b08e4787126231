#include "variant_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "cli.h"
#include "output_file.h"
#include "parse_values.h"
#include "partial_set.h"
#include "specular/reference.h"
#include "specular/variants/variant.h"
#include "usage_error.h"

namespace specular {
namespace tb {

void ErrorMeasure::add(double error, long long cos_code, unsigned n) {
  if (sum_by_n.size() <= n) sum_by_n.resize(n + 1, 0.0);
  sum_by_n[n] += error;
  ++values;
  if (error > max_abs) {  // strict: the first (smallest n, then cos code) keeps a tie
    max_abs = error;
    max_cos_code = cos_code;
    max_n = n;
  }
}

void ErrorMeasure::merge(const ErrorMeasure& o) {
  if (o.values == 0) return;
  if (sum_by_n.size() < o.sum_by_n.size()) sum_by_n.resize(o.sum_by_n.size(), 0.0);
  for (std::size_t n = 0; n < o.sum_by_n.size(); ++n) sum_by_n[n] += o.sum_by_n[n];
  values += o.values;
  const bool earlier = o.max_n < max_n || (o.max_n == max_n && o.max_cos_code < max_cos_code);
  if (o.max_abs > max_abs || (o.max_abs == max_abs && earlier)) {
    max_abs = o.max_abs;
    max_cos_code = o.max_cos_code;
    max_n = o.max_n;
  }
}

double ErrorMeasure::mean_abs() const {
  double total = 0;
  for (const double sum : sum_by_n) total += sum;  // in n order, whatever the sharding
  return values == 0 ? 0.0 : total / static_cast<double>(values);
}

VariantError measure_variant_error(const std::string& name, const ErrorSweepRange& range) {
  const auto started = std::chrono::steady_clock::now();
  const Config config{};
  const Formats formats(config.widths);
  const std::unique_ptr<variants::Variant> variant = variants::make_variant(name, config);
  VariantError e;
  e.name = name;
  e.range = range;
  // Every variant also against the patent's formula: the reference of those that compute
  // it (patent, one_pass), the others' distance from it.
  e.has_formula = true;
  const long long codes = 1LL << formats.cos.frac_bits;  // cos 1.0: codes 0..2^16
  const double cos_lsb = formats.cos.lsb(), norm_lsb = formats.norm.lsb(), out_lsb = formats.out.lsb();
  constexpr double intensity = 255;
  Operands op;
  op.rgb = {255, 255, 255};
  for (unsigned n = range.n_first; n <= range.n_last; ++n) {
    if (!shard_has_n(n, range.shard)) continue;
    const double k = reference::k(n, config.normalisation, config.constants, formats.cos.frac_bits);
    op.n = n;
    for (long long code = 0; code <= codes; ++code) {
      op.cos = code;
      const variants::VariantResult r = variant->run(op);
      const double cos_q = static_cast<double>(code) * cos_lsb;
      const double lobe = static_cast<double>(r.lobe) * norm_lsb;
      const double exact = k * reference::exact_lobe(cos_q, n);
      e.lobe.add(std::abs(lobe - exact), code, n);
      for (int ch = 0; ch < 3; ++ch)
        e.out.add(std::abs(static_cast<double>(r.out[ch]) * out_lsb - exact * intensity), code, n);
      if (e.has_formula) {
        const double formula =
            k * reference::approx(cos_q, n, config.saturation, formats.cos.frac_bits, config.constants);
        e.formula_lobe.add(std::abs(lobe - formula), code, n);
        for (int ch = 0; ch < 3; ++ch)
          e.formula_out.add(std::abs(static_cast<double>(r.out[ch]) * out_lsb - formula * intensity), code, n);
      }
      ++e.operations;
    }
  }
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return e;
}

namespace {

Json at_json(const ErrorMeasure& m) {
  return Json{{"cos_code", m.max_cos_code}, {"n", m.max_n}, {"cos", std::ldexp(double(m.max_cos_code), -16)}};
}

void measure_fields(Json& j, const std::string& prefix, const ErrorMeasure& m) {
  j[prefix + "_max_abs"] = m.max_abs;
  j[prefix + "_mean_abs"] = m.mean_abs();
  j[prefix + "_max_at"] = at_json(m);
}

Json measure_partial(const ErrorMeasure& m) {
  Json sums = Json::array();
  for (std::size_t n = 0; n < m.sum_by_n.size(); ++n)
    if (m.sum_by_n[n] != 0) sums.push_back(Json::array({n, m.sum_by_n[n]}));
  return Json{{"max_abs", m.max_abs}, {"cos_code", m.max_cos_code}, {"n", m.max_n},
              {"values", m.values},  {"sums_by_n", sums}};
}

ErrorMeasure measure_from_partial(const Json& j) {
  ErrorMeasure m;
  m.max_abs = j.at("max_abs").get<double>();
  m.max_cos_code = j.at("cos_code").get<long long>();
  m.max_n = j.at("n").get<unsigned>();
  m.values = j.at("values").get<std::uint64_t>();
  for (const Json& pair : j.at("sums_by_n")) {
    const std::size_t n = pair.at(0).get<std::size_t>();
    if (n > 100000) throw std::out_of_range("n " + std::to_string(n));
    if (m.sum_by_n.size() <= n) m.sum_by_n.resize(n + 1, 0.0);
    m.sum_by_n[n] = pair.at(1).get<double>();
  }
  return m;
}

Json settings_of(const VariantError& e) {
  return Json{{"name", e.name},
              {"config", "default"},
              {"rgb", 255},
              {"n_first", e.range.n_first},
              {"n_last", e.range.n_last}};
}

}  // namespace

Json variant_error_json(const VariantError& e) {
  Json j;
  j["name"] = e.name;
  measure_fields(j, "lobe", e.lobe);
  measure_fields(j, "out", e.out);
  if (e.has_formula) {
    Json formula;
    measure_fields(formula, "lobe", e.formula_lobe);
    measure_fields(formula, "out", e.formula_out);
    j["patent_formula"] = formula;  // against K(n)·A in double (docs/accuracy.md's norm_ref)
  }
  j["operations"] = e.operations;
  j["seconds"] = e.seconds;
  j["settings"] = settings_of(e);
  return j;
}

Json variant_error_partial(const VariantError& e) {
  Json j;
  j["kind"] = variant_error_kind;
  j["version"] = partial_version;
  j["commit"] = build_commit();
  j["settings"] = settings_of(e);
  j["shard"] = Json{{"index", e.range.shard.index}, {"count", e.range.shard.count}};
  Json summary{{"operations", e.operations}, {"lobe", measure_partial(e.lobe)}, {"out", measure_partial(e.out)}};
  if (e.has_formula) {
    summary["formula_lobe"] = measure_partial(e.formula_lobe);
    summary["formula_out"] = measure_partial(e.formula_out);
  }
  j["summary"] = summary;
  j["timing"] = Json{{"wall_seconds", e.seconds}, {"cpu_seconds", process_cpu_seconds()}};
  return j;
}

VariantError merge_variant_error(const std::vector<std::string>& files) {
  const std::vector<PartialFile> parts = read_complete_set(files, variant_error_kind);
  VariantError e;
  for (const PartialFile& p : parts) {
    try {
      const Json& s = p.json.at("settings");
      const Json& summary = p.json.at("summary");
      if (&p == &parts.front()) {
        e.name = s.at("name").get<std::string>();
        e.range.n_first = s.at("n_first").get<unsigned>();
        e.range.n_last = s.at("n_last").get<unsigned>();
        e.has_formula = summary.contains("formula_lobe");
      }
      e.operations += summary.at("operations").get<std::uint64_t>();
      e.lobe.merge(measure_from_partial(summary.at("lobe")));
      e.out.merge(measure_from_partial(summary.at("out")));
      if (e.has_formula) {
        e.formula_lobe.merge(measure_from_partial(summary.at("formula_lobe")));
        e.formula_out.merge(measure_from_partial(summary.at("formula_out")));
      }
      e.seconds += p.json.at("timing").at("wall_seconds").get<double>();
    } catch (const std::exception& x) {
      throw UsageError("--merge: '" + p.path + "' is not a complete partial result: " + x.what());
    }
  }
  const std::uint64_t expected =
      std::uint64_t{e.range.n_last - e.range.n_first + 1} * ((std::uint64_t{1} << Formats(Widths{}).cos.frac_bits) + 1);
  if (e.operations != expected)
    throw UsageError("--merge: the shards hold " + std::to_string(e.operations) + " operations, the run has " +
                     std::to_string(expected) + " (a shard was cut short?)");
  return e;
}

namespace {

const char* const description = R"(specular_variant_error: a design variant's exhaustive error (issue 26, docs/design_space.md)

The runs:
  specular_variant_error NAME [--json FILE] [--n FIRST:LAST] [--shard I/N --partial FILE]
  specular_variant_error --merge FILE... [--json FILE]
  specular_variant_error --all [--json FILE] [--n FIRST:LAST]
                                         every registered variant in turn (JSON: an array)
  specular_variant_error --list          the registered variants' names, one a line
)";

const char* const footer = R"(Runs variant NAME's C++ model on every cos code 0..65536 (U1.16) x every n in FIRST..LAST
(default 1:1000) at the default configuration and R = G = B = 255, and reports max and
mean |lobe - K(n)*cos^n| (multiplier 39's S10.20) and |pin - K(n)*cos^n*255| (pins 24-26,
S18.13, every channel), each max with its (cos code, n), the operation count and wall
seconds; also against the patent's formula K(n)*A in double ("patent_formula": the
reference of the variants that compute it, the others' distance from it). --shard I/N runs the n with (n - 1) mod N == I and writes the partial
result to --partial FILE (without --shard: the whole run's, shard 0/1); --merge adds a complete set of them up into the unsharded run's
figures, bit for bit (seconds: the shards' sum).

Exit status: 0 done; 2 bad option, name or partial set; 3 internal error.)";

void print_measure(std::ostream& out, const char* label, const ErrorMeasure& m) {
  out << "  " << std::left << std::setw(30) << label << std::right << " max " << std::setprecision(6)
      << m.max_abs << " at cos code " << m.max_cos_code << " (cos " << std::setprecision(8)
      << std::ldexp(double(m.max_cos_code), -16) << "), n " << m.max_n << "; mean "
      << std::setprecision(6) << m.mean_abs() << '\n';
}

void print_text(std::ostream& out, const VariantError& e) {
  out << "variant " << e.name << ": " << e.operations << " operations (cos codes 0..65536 x n "
      << e.range.n_first << ".." << e.range.n_last;
  if (!e.range.shard.whole()) out << ", shard " << e.range.shard.text();
  out << "), default config, R = G = B = 255\n";
  print_measure(out, "|lobe - K(n)*cos^n|", e.lobe);
  print_measure(out, "|out - K(n)*cos^n*255|", e.out);
  if (e.has_formula) {
    print_measure(out, "|lobe - K(n)*A| (formula)", e.formula_lobe);
    print_measure(out, "|out - K(n)*A*255| (formula)", e.formula_out);
  }
  out << "  wall " << std::fixed << std::setprecision(2) << e.seconds << " s\n" << std::defaultfloat;
}

void write_json(const std::string& path, const Json& json) {
  AtomicOutputStream file(path, "--json");
  file.stream() << json.dump(2) << '\n';
  file.commit();
}

/// --n FIRST:LAST, 1 <= FIRST <= LAST <= 1000.
ErrorSweepRange parse_n_range(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) throw UsageError("--n: '" + text + "' is not FIRST:LAST (e.g. 1:1000)");
  const long long first = parse_integer(text.substr(0, colon), "FIRST", "[1, 1000]");
  const long long last = parse_integer(text.substr(colon + 1), "LAST", "[FIRST, 1000]");
  if (first < 1 || last > 1000 || first > last)
    throw UsageError("--n: " + text + " is not FIRST:LAST with 1 <= FIRST <= LAST <= 1000");
  ErrorSweepRange range;
  range.n_first = static_cast<unsigned>(first);
  range.n_last = static_cast<unsigned>(last);
  return range;
}

std::string variant_list() {
  std::string list;
  for (const std::string& name : variants::variant_names()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

/// The command line, declared (run_support/cli.h).
struct VariantErrorOptions {
  std::string name, json_path, partial_path;
  bool list = false, all = false;
  std::vector<std::string> merge_files;
  ErrorSweepRange n_range;
  Shard shard;
};

void add_options(specular::cli::Command& app, VariantErrorOptions& o) {
  app.add_option("NAME", o.name, "the variant, one of: " + variant_list());
  app.add_flag("--list", o.list, "the registered variants' names, one a line (nothing else with it)");
  app.add_flag("--all", o.all, "every registered variant in turn (JSON: an array); with --json and --n only");
  app.add_option("--merge", o.merge_files, "add a complete set of partial results up (with --json only)")
      ->type_name("FILE")
      ->expected(1, -1);
  app.add_option("--json", o.json_path, "write the figures as JSON there")
      ->type_name("FILE")
      ->check(cli::parsed_by([](const std::string& v) {
        if (v.empty()) throw UsageError("the file name is empty");
      }));
  cli::add_parsed(app, "--n", o.n_range, parse_n_range, "the n measured, 1 <= FIRST <= LAST <= 1000 (default 1:1000)")
      ->type_name("FIRST:LAST");
  cli::add_parsed(app, "--shard", o.shard, parse_shard, "the n with (n - 1) mod N == I; needs --partial")
      ->type_name("I/N");
  app.add_option("--partial", o.partial_path, "write this run's partial result (without --shard: the whole run's)")
      ->type_name("FILE")
      ->check(cli::parsed_by([](const std::string& v) {
        if (v.empty()) throw UsageError("the file name is empty");
      }));
}

int run(const specular::cli::Command& app, const VariantErrorOptions& o, std::ostream& out) {
  const auto only = [&](const std::string& mode, const std::vector<std::string>& allowed) {
    for (const std::string& name : app.given()) {
      if (name == mode || name == "--help" || name == "--version") continue;
      if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
        throw UsageError(mode + ": " + name + " does not apply" +
                         (allowed.empty() ? std::string(" (nothing else with it)") : " (allowed: " + [&] {
                           std::string list;
                           for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
                           return list;
                         }() + ")"));
    }
  };
  if (o.list) {
    only("--list", {});
    for (const std::string& name : variants::variant_names()) out << name << '\n';
    return 0;
  }
  if (o.all) {  // every registered variant, one after the other
    only("--all", {"--json", "--n"});
    std::optional<AtomicOutputStream> file;
    if (!o.json_path.empty()) file.emplace(o.json_path, "--json");
    Json all = Json::array();
    for (const std::string& name : variants::variant_names()) {
      const VariantError e = measure_variant_error(name, o.n_range);
      print_text(out, e);
      all.push_back(variant_error_json(e));
    }
    if (file) {
      file->stream() << all.dump(2) << '\n';
      file->commit();
    }
    return 0;
  }
  const bool merge = !o.merge_files.empty();
  if (merge) only("--merge", {"--json"});
  const std::string& name = o.name;
  const std::string& json_path = o.json_path;
  const std::string& partial_path = o.partial_path;
  const std::vector<std::string>& files = o.merge_files;
  const bool shard_given = app.count("--shard") > 0;
  ErrorSweepRange range = o.n_range;
  range.shard = o.shard;
  VariantError e;
  if (merge) {
    e = merge_variant_error(files);
  } else {
    const auto names = variants::variant_names();
    if (name.empty())
      throw UsageError("give a variant's NAME (one of: " + variant_list() + "), --merge FILE... or --list");
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw UsageError("unknown variant '" + name + "' (known: " + variant_list() + ")");
    if (shard_given && partial_path.empty())
      throw UsageError("--shard I/N needs --partial FILE (a shard's figures are merged from its file)");
    if (range.shard.count > range.n_last - range.n_first + 1)
      throw UsageError("--shard: N = " + std::to_string(range.shard.count) + " is more than the run's " +
                       std::to_string(range.n_last - range.n_first + 1) + " values of n (split by n)");
    std::optional<AtomicOutputStream> partial;  // proves the path writable before the run
    if (!partial_path.empty()) partial.emplace(partial_path, "--partial");
    e = measure_variant_error(name, range);
    if (partial) {
      partial->stream() << variant_error_partial(e).dump(2) << '\n';
      partial->commit();
    }
  }
  print_text(out, e);
  if (!json_path.empty()) write_json(json_path, variant_error_json(e));
  return 0;
}

}  // namespace

int run_variant_error(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  specular::cli::Command app{description, "specular_variant_error"};
  cli::house_rules(app, footer);
  VariantErrorOptions options;
  add_options(app, options);
  return cli::run(
      app, args,
      [&] {
        try {
          return run(app, options, out);
        } catch (const UsageError&) {
          throw;  // cli::run: exit 2
        } catch (const std::exception& e) {
          err << "specular_variant_error: internal error: " << e.what() << '\n';
          return 3;
        }
      },
      out, err);
}

}  // namespace tb
}  // namespace specular
