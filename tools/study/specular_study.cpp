// specular_study: measures the patent's two claims — that 1 − ½·log2(1 − n·log2 cos λ)
// approximates cos^n λ, and that 2π/(n+2) conserves energy — next to the alternatives,
// and justifies the fixed-point widths. Writes CSV files; scripts/flows/design_space/plot_study.py draws
// them; docs/study.md reads them. Progress goes to stderr, a summary to stdout and to
// <out>/summary.txt.
//
// Sharded (issue 25, docs/farm.md): --shard I/N runs the stages s with s mod N = I (six
// stages, each one farm task at most), --partial FILE writes what the merge needs (the
// files the shard wrote and the stages' figures for the summary, read back exactly by
// nlohmann-json), and --merge gathers a complete set into one folder: the unsharded run's
// files, byte for byte, and its summary.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "cli.h"
#include "constants_search.h"
#include "csv.h"
#include "energy_study.h"
#include "error_study.h"
#include "sphere_study.h"
#include "study_options.h"
#include "width_study.h"

#include "json.h"
#include "partial_set.h"
#include "shard.h"
#include "usage_error.h"

using namespace specular;
using namespace specular::study;

namespace {

std::string summarise(const ErrorSummary& errors, const std::vector<EnergyRow>& energy,
                      const std::vector<DeviceEnergyRow>& device_energy,
                      const std::vector<WidthResult>& widths, double seconds) {
  std::ostringstream s;
  char line[256];
  s << "Maximum |f - cos^n| over every cos code and every n visited:\n";
  for (Method m : all_methods) {
    const auto& w = errors.worst[static_cast<std::size_t>(m)];
    std::snprintf(line, sizeof line, "  %-16s %.6f  (n = %u, cos = %.6f)\n", method_name(m),
                  w.value, w.n, w.at_cos);
    s << line;
  }
  std::snprintf(line, sizeof line, "  %-16s %.3g  (n = %u, cos = %.6f)  [fixed-point error]\n",
                "device-formula", errors.device_vs_formula.value, errors.device_vs_formula.n,
                errors.device_vs_formula.at_cos);
  s << line;

  s << "Hemisphere integral (equation 6) at n = 1, 10, 100, 1000:\n";
  s << "  policy  n      exact      formula    device     schlick    us5739820\n";
  for (const EnergyRow& row : energy) {
    if (row.n != 1 && row.n != 10 && row.n != 100 && row.n != 1000) continue;
    std::snprintf(line, sizeof line, "  %-7s %-5u  %-9.4g  %-9.4g  %-9.4g  %-9.4g  %-9.4g\n",
                  to_string(row.policy), row.n, row.scaled.exact, row.scaled.formula_clamp,
                  row.device_clamp, row.scaled.schlick, row.scaled.us5739820);
    s << line;
  }

  s << "Normalisation device-energy: equation-6 integral of multiplier 39, every n visited:\n";
  for (Constants c : {Constants::patent, Constants::minimax_half, Constants::minimax}) {
    double lo = 1e9, hi = -1e9, energy_lo = 1e9, energy_hi = -1e9;
    for (const DeviceEnergyRow& row : device_energy) {
      if (row.constants != c) continue;
      lo = std::min(lo, row.device_energy), hi = std::max(hi, row.device_energy);
      energy_lo = std::min(energy_lo, row.energy), energy_hi = std::max(energy_hi, row.energy);
    }
    std::snprintf(line, sizeof line,
                  "  constants %-12s device-energy %.6f ... %.6f   (energy: %.4f ... %.4f)\n",
                  to_string(c), lo, hi, energy_lo, energy_hi);
    s << line;
  }

  s << "Widths (defaults marked *): max |A_device - A_formula|, ROM 5 bits:\n";
  const Widths d;
  for (const WidthResult& r : widths) {
    if (r.config.sweep != "rom5_addr") continue;
    const bool is_default = r.config.widths.rom5_addr_bits == d.rom5_addr_bits;
    std::snprintf(line, sizeof line, "  ROM 5 address %2d bits%s  %.3g  (%ld bits)\n",
                  r.config.widths.rom5_addr_bits, is_default ? "*" : " ", r.max_err_vs_formula,
                  r.rom5_bits);
    s << line;
  }
  std::snprintf(line, sizeof line, "Study time: %.1f s\n", seconds);
  s << line;
  return s.str();
}

// What the summary needs from each stage, as JSON (doubles read back exactly).
tb::Json worst_json(const ErrorSummary::Worst& w) { return tb::Json{{"value", w.value}, {"n", w.n}, {"at_cos", w.at_cos}}; }
ErrorSummary::Worst worst_from(const tb::Json& j) {
  return {j.at("value").get<double>(), j.at("n").get<unsigned>(), j.at("at_cos").get<double>()};
}

// The stages: constants search, error study, energy integrals, device-energy integrals,
// width exploration, sphere renders (a shard runs every count-th of them).
constexpr std::size_t stage_count = 6;

struct StudyResults {
  ErrorSummary errors;
  std::vector<EnergyRow> energy;
  std::vector<DeviceEnergyRow> device_energy;
  std::vector<WidthResult> widths;
};

tb::Json results_json(const StudyResults& r, const std::vector<bool>& ran) {
  tb::Json j = tb::Json::object();
  if (ran[1]) {
    tb::Json worst = tb::Json::array();
    for (const auto& w : r.errors.worst) worst.push_back(worst_json(w));
    j["errors"] = {{"worst", worst}, {"device_vs_formula", worst_json(r.errors.device_vs_formula)}};
  }
  if (ran[2]) {
    tb::Json rows = tb::Json::array();
    for (const EnergyRow& e : r.energy)
      rows.push_back({{"n", e.n}, {"policy", to_string(e.policy)}, {"exact", e.scaled.exact},
                      {"formula_clamp", e.scaled.formula_clamp}, {"device_clamp", e.device_clamp},
                      {"schlick", e.scaled.schlick}, {"us5739820", e.scaled.us5739820}});
    j["energy"] = rows;
  }
  if (ran[3]) {
    tb::Json rows = tb::Json::array();
    for (const DeviceEnergyRow& e : r.device_energy)
      rows.push_back({{"n", e.n}, {"constants", to_string(e.constants)}, {"device_energy", e.device_energy},
                      {"energy", e.energy}});
    j["device_energy"] = rows;
  }
  if (ran[4]) {
    tb::Json rows = tb::Json::array();
    for (const WidthResult& w : r.widths)
      rows.push_back({{"sweep", w.config.sweep}, {"rom5_addr_bits", w.config.widths.rom5_addr_bits},
                      {"max_err_vs_formula", w.max_err_vs_formula}, {"rom5_bits", w.rom5_bits}});
    j["widths"] = rows;
  }
  return j;
}

void results_from(const tb::Json& j, StudyResults& r) {
  if (j.contains("errors")) {
    const tb::Json& worst = j.at("errors").at("worst");
    for (std::size_t m = 0; m < r.errors.worst.size(); ++m) r.errors.worst[m] = worst_from(worst.at(m));
    r.errors.device_vs_formula = worst_from(j.at("errors").at("device_vs_formula"));
  }
  if (j.contains("energy"))
    for (const tb::Json& e : j.at("energy")) {
      EnergyRow row;
      row.n = e.at("n").get<unsigned>();
      row.policy = parse_normalisation(e.at("policy").get<std::string>());
      row.scaled.exact = e.at("exact").get<double>();
      row.scaled.formula_clamp = e.at("formula_clamp").get<double>();
      row.device_clamp = e.at("device_clamp").get<double>();
      row.scaled.schlick = e.at("schlick").get<double>();
      row.scaled.us5739820 = e.at("us5739820").get<double>();
      r.energy.push_back(row);
    }
  if (j.contains("device_energy"))
    for (const tb::Json& e : j.at("device_energy")) {
      DeviceEnergyRow row;
      row.n = e.at("n").get<unsigned>();
      row.constants = parse_constants(e.at("constants").get<std::string>());
      row.device_energy = e.at("device_energy").get<double>();
      row.energy = e.at("energy").get<double>();
      r.device_energy.push_back(row);
    }
  if (j.contains("widths"))
    for (const tb::Json& e : j.at("widths")) {
      WidthResult row;
      row.config.sweep = e.at("sweep").get<std::string>();
      row.config.widths.rom5_addr_bits = e.at("rom5_addr_bits").get<int>();
      row.max_err_vs_formula = e.at("max_err_vs_formula").get<double>();
      row.rom5_bits = e.at("rom5_bits").get<long>();
      r.widths.push_back(row);
    }
}

void write_summary(const StudyOptions& options, const StudyResults& r, double seconds) {
  const std::string summary = summarise(r.errors, r.energy, r.device_energy, r.widths, seconds);
  std::cout << summary;
  std::ofstream file(options.out_dir + "/summary.txt");
  file << summary;
  if (!file) throw std::runtime_error("cannot write '" + options.out_dir + "/summary.txt'");
}

tb::Json study_settings(bool quick) {
  return tb::Json{{"tool", "specular_study"}, {"quick", quick}, {"stages", stage_count}};
}

// --merge: one complete set of shards -> the unsharded run's folder.
int merge(const StudyOptions& options) {
  const std::vector<tb::PartialFile> parts = tb::read_complete_set(options.merge_files, "specular_study partial");
  namespace fs = std::filesystem;
  std::set<std::size_t> stages;
  StudyResults results;
  double seconds = 0;
  for (const tb::PartialFile& p : parts) {
    for (const auto& s : p.json.at("summary").at("stages")) stages.insert(s.get<std::size_t>());
    for (const auto& f : p.json.at("summary").at("files")) {
      const fs::path from = fs::path(p.json.at("summary").at("out_dir").get<std::string>()) / f.get<std::string>();
      if (!fs::exists(from))
        throw tb::UsageError("--merge: '" + p.path + "' names " + from.string() + ", which is not there");
    }
    results_from(p.json.at("summary").at("results"), results);
    seconds += p.json.at("timing").at("wall_seconds").get<double>();
  }
  if (stages.size() != stage_count)
    throw tb::UsageError("--merge: the shards ran " + std::to_string(stages.size()) + " of the " +
                         std::to_string(stage_count) + " stages");
  make_directory(options.out_dir);
  for (const tb::PartialFile& p : parts)
    for (const auto& f : p.json.at("summary").at("files"))
      fs::copy_file(fs::path(p.json.at("summary").at("out_dir").get<std::string>()) / f.get<std::string>(),
                    fs::path(options.out_dir) / f.get<std::string>(), fs::copy_options::overwrite_existing);
  write_summary(options, results, seconds);
  return 0;
}

}  // namespace

// libsystemc.so comes with the IP library and refers to the program's sc_main. This
// tool never starts SystemC, but in a sanitizer build the library stays loaded (it
// exports libstdc++ code the instrumented objects use) and binds sc_main at load time.
extern "C" int sc_main(int, char**) { return 0; }

namespace {

int run_study(const StudyOptions& options) {
  const tb::Shard shard = tb::parse_shard(options.shard);
  if (!options.merge_files.empty()) {
    try {
      return merge(options);
    } catch (const tb::UsageError& e) {
      std::cerr << "specular_study: " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "specular_study: " << e.what() << "\n";
      return 1;
    }
  }
  try {
    namespace fs = std::filesystem;
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = tb::process_cpu_seconds();
    make_directory(options.out_dir);
    std::cerr << "specular_study: writing to " << options.out_dir
              << (options.quick ? " (quick mode)" : "")
              << (shard.whole() ? "" : ", shard " + shard.text() + " of the stages") << "\n";
    std::vector<bool> ran(stage_count);
    for (std::size_t s = 0; s < stage_count; ++s) ran[s] = s % shard.count == shard.index;
    // The files this run writes: those written since it started.
    std::map<std::string, fs::file_time_type> before;
    for (const auto& e : fs::directory_iterator(options.out_dir))
      before[e.path().filename().string()] = e.last_write_time();
    StudyResults r;
    if (ran[0]) {
      std::cerr << "constants search (specular_constants)\n";
      write_constants_csv(constants_table(16), options.out_dir + "/constants_search.csv");
    }
    if (ran[1]) r.errors = run_error_study(options);
    if (ran[2]) r.energy = run_energy_study(options);
    if (ran[3]) r.device_energy = run_device_energy_study(options);
    if (ran[4]) r.widths = run_width_study(options);
    if (ran[5]) {
      std::cerr << "sphere renders\n";
      run_sphere_study(options);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (shard.whole()) write_summary(options, r, seconds);
    if (!options.partial.empty()) {
      tb::Json files = tb::Json::array(), stages = tb::Json::array();
      std::set<std::string> written;
      for (const auto& e : fs::directory_iterator(options.out_dir)) {
        const std::string name = e.path().filename().string();
        const auto was = before.find(name);
        if (name != "summary.txt" && e.is_regular_file() && (was == before.end() || was->second != e.last_write_time()))
          written.insert(name);
      }
      for (const std::string& name : written) files.push_back(name);
      for (std::size_t s = 0; s < stage_count; ++s)
        if (ran[s]) stages.push_back(s);
      tb::Json j;
      j["kind"] = "specular_study partial";
      j["version"] = tb::partial_version;
      j["commit"] = tb::build_commit();
      j["settings"] = study_settings(options.quick);
      j["shard"] = tb::Json{{"index", shard.index}, {"count", shard.count}};
      j["summary"] = tb::Json{{"stages", stages}, {"files", files},
                              {"out_dir", fs::absolute(options.out_dir).lexically_normal().string()},
                              {"results", results_json(r, ran)}};
      j["timing"] = tb::Json{{"wall_seconds", seconds}, {"cpu_seconds", tb::process_cpu_seconds() - cpu_start}};
      std::ofstream out(options.partial);
      out << tb::dump_json(j) << "\n";
      if (!out) throw std::runtime_error("cannot write '" + options.partial + "'");
      if (!shard.whole())
        std::cout << "specular_study: shard " << shard.text() << ": " << stages.size() << " stage(s), "
                  << files.size() << " file(s) in " << options.out_dir << "; merge with --merge\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "specular_study: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  specular::cli::Command app{"Measures the device's approximation of cos^n, its energy integrals and its fixed-point\n"
                             "widths, and writes CSV files for scripts/flows/design_space/plot_study.py.\n"
                             "  specular_study [--out DIR] [--quick] [--workers N] [--quiet] [--shard I/N] [--partial FILE]\n"
                             "  specular_study --merge PARTIAL... [--out DIR]",
                             "specular_study"};
  cli::house_rules(app, "Exit status: 0 done, 1 a stage failed or a file could not be written, 2 bad usage "
                        "or a refused merge.");
  StudyOptions options;
  add_study_options(app, options);
  return cli::run(app, argc, argv, [&] { return run_study(options); });
}
