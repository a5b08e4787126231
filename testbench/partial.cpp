#include "partial.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "cli.h"
#include "output_file.h"
#include "run_models.h"
#include "usage_error.h"

namespace specular {
namespace tb {

namespace {

std::string hex64(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace

Json partial_settings(const RunDescription& whole, const std::array<long long, 3>& rgb,
                      std::uint64_t input_checksum) {
  Json s = run_settings_json(whole);
  s["text_rows"] = whole.text_rows;
  Json widths;
  for (const WidthField& field : width_fields()) widths[field.name] = whole.config.widths.*field.member;
  s["widths"] = widths;
  s["rgb"] = rgb;
  s["input_checksum"] = hex64(input_checksum);
  return s;
}

Json partial_json(const Json& settings, const Shard& shard, const Summary& summary,
                  const ShardTiming& timing) {
  Json j;
  j["kind"] = partial_kind;
  j["version"] = partial_version;
  j["commit"] = build_commit();
  j["settings"] = settings;
  j["shard"] = Json{{"index", shard.index}, {"count", shard.count}};
  j["summary"] = summary_json(summary, true);
  j["timing"] = Json{{"wall_seconds", timing.wall_seconds},
                     {"cpu_seconds", timing.cpu_seconds},
                     {"host", host_name()}};
  return j;
}

namespace {

void merge_worst(Worst& into, const Worst& w, bool first) {
  // The unsharded run keeps the first operation with the largest error: the largest
  // error, and among equal errors the smallest index.
  if (first || w.error > into.error || (w.error == into.error && w.at < into.at)) {
    const double tolerance_used = std::max(into.tolerance_used, w.tolerance_used);
    into = w;
    into.tolerance_used = tolerance_used;
  } else {
    into.tolerance_used = std::max(into.tolerance_used, w.tolerance_used);
  }
}

RunDescription description_from_settings(const Json& s) {
  RunDescription run;
  run.model = s.at("model").get<std::string>();
  run.stimulus = s.at("stimulus").get<std::string>();
  run.config.normalisation = parse_normalisation(s.at("normalisation").get<std::string>());
  run.config.saturation = parse_saturation(s.at("saturation").get<std::string>());
  run.config.constants = parse_constants(s.at("constants").get<std::string>());
  for (const WidthField& field : width_fields())
    run.config.widths.*field.member = s.at("widths").at(field.name).get<int>();
  run.clock_period_ps = s.at("clock_period_ps").get<std::uint64_t>();
  run.operations = s.at("operations").get<std::size_t>();
  run.text_rows = false;  // a merge has no rows: the summary only
  return run;
}

}  // namespace

int run_merge(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> files;
  OutputFormat format = OutputFormat::text;
  std::string output_path, partial_path;
  specular::cli::Command app{"specular_tb --merge: every shard's partial result merged into the unsharded run's report\n"
                             "(refusing a missing, duplicated or mismatched shard).",
                             "specular_tb --merge"};
  cli::house_rules(app);
  app.add_option("FILE", files, "the partial results, one per shard")->required()->expected(1, -1);
  cli::add_parsed(app, "--format", format, parse_output_format, "text (default) or json")->type_name("text|json");
  app.add_option("--output", output_path, "write the report there")->type_name("FILE")->check(cli::file_name());
  app.add_option("--partial", partial_path, "also write the merged partial result")
      ->type_name("FILE")
      ->check(cli::file_name());
  try {
    switch (cli::parse(app, args)) {
      case cli::Parsed::help:
        out << app.help();
        return 0;
      case cli::Parsed::version:
        out << "specular_tb " << cli::version() << '\n';
        return 0;
      case cli::Parsed::run:
        break;
    }
  } catch (const cli::CommandLineError& e) {
    if (e.missing_required()) throw UsageError("--merge needs the partial files of every shard (FILE...)");
    std::string message = e.what();
    const auto see = message.find(" (see --help)");  // run_testbench says where to look
    if (see != std::string::npos) message.erase(see, 13);
    throw UsageError("--merge: " + message);
  } catch (const UsageError& e) {
    throw UsageError(std::string("--merge: ") + e.what());
  }
  if (format == OutputFormat::csv)
    throw UsageError("--merge: --format csv is not available (a merge has no rows): text or json");

  const std::vector<PartialFile> parts = read_complete_set(files, partial_kind);
  std::vector<Summary> summaries;
  for (const PartialFile& p : parts) {
    try {
      summaries.push_back(summary_from_json(p.json.at("summary")));
    } catch (const std::exception& e) {
      throw UsageError("--merge: '" + p.path + "' is not a complete partial result: " + e.what());
    }
  }
  const PartialFile& first = parts.front();
  const std::size_t count = first.shard.count;
  const Json& settings = first.json.at("settings");
  RunDescription run;
  try {
    run = description_from_settings(settings);
  } catch (const std::exception& e) {
    throw UsageError("--merge: '" + first.path + "' has unreadable settings: " + e.what());
  }

  Summary total;
  ShardTiming timing;  // summed CPU; wall: the longest shard
  Json shards = Json::array();
  bool any = false;
  for (std::size_t i = 0; i < parts.size(); ++i) {  // in shard order (read_complete_set)
    const PartialFile* p = &parts[i];
    const Summary& s = summaries[i];
    total.count += s.count;
    total.failures += s.failures;
    total.approx_failures += s.approx_failures;
    total.norm_failures += s.norm_failures;
    total.out_failures += s.out_failures;
    total.cycles_failures += s.cycles_failures;
    total.checksum += s.checksum;
    total.energy_pj += s.energy_pj;  // each shard from a reset device: their sum
    total.energy_bus_pj += s.energy_bus_pj;
    const Json& t = p->json.at("timing");
    timing.cpu_seconds += t.value("cpu_seconds", 0.0);
    timing.wall_seconds = std::max(timing.wall_seconds, t.value("wall_seconds", 0.0));
    shards.push_back(Json{{"index", p->shard.index}, {"file", p->path}, {"operations", s.count},
                          {"timing", t}});
    if (s.count == 0) continue;
    merge_worst(total.approx, s.approx, !any);
    merge_worst(total.norm, s.norm, !any);
    merge_worst(total.norm_exact, s.norm_exact, !any);
    merge_worst(total.out, s.out, !any);
    total.cycles_min = any ? std::min(total.cycles_min, s.cycles_min) : s.cycles_min;
    total.cycles_max = any ? std::max(total.cycles_max, s.cycles_max) : s.cycles_max;
    any = true;
  }
  if (total.count != run.operations)
    throw UsageError("--merge: the shards hold " + std::to_string(total.count) +
                     " computations, the run has " + std::to_string(run.operations) +
                     " (a shard was cut short?)");

  std::optional<AtomicOutputStream> output_file;
  if (!output_path.empty()) output_file.emplace(output_path, "--output");
  std::optional<AtomicOutputStream> partial_file;
  if (!partial_path.empty()) partial_file.emplace(partial_path, "--partial");
  std::ostream& report_stream = output_file ? output_file->stream() : out;
  const std::unique_ptr<Report> report = make_report(format, report_stream, err);
  report->begin(run);
  report->end(total, -1);  // no run time: the text stays reproducible
  if (partial_file) {
    Json merged = partial_json(settings, Shard{}, total, timing);
    merged["commit"] = first.json.at("commit");
    merged["timing"]["wall_seconds_longest_shard"] = timing.wall_seconds;
    merged["merged_from"] = shards;
    partial_file->stream() << merged.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
    partial_file->commit();
  }
  report_stream.flush();
  if (!report_stream) throw UsageError("cannot write the report (disk full?)");
  if (output_file) output_file->commit();
  err << "specular_tb --merge: " << count << " shard(s), " << total.count
      << " computation(s), results checksum " << summary_json(total, true).at("checksum").get<std::string>()
      << ", CPU " << timing.cpu_seconds << " s in all\n";
  return total.pass() ? 0 : 1;
}

}  // namespace tb
}  // namespace specular
