#include "testbench.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <utility>

#include "input.h"
#include "options.h"
#include "output_file.h"
#include "partial.h"
#include "progress.h"
#include "report.h"
#include "run_models.h"
#include "scoreboard.h"
#include "specular/core.h"
#include "specular/systemc.h"
#include "usage_error.h"
#include "version.h"

namespace specular {
namespace tb {

namespace {

struct Plan {
  std::unique_ptr<StimulusSource> source;
  std::string description;  // for the report header
  std::size_t whole_operations = 0;   // the unsharded run's count
  std::uint64_t input_checksum = 0;   // --input: every operation of the file (partial.h)
};

Plan make_plan(const Options& o, const Formats& formats) {
  Plan plan;
  switch (o.stimulus) {
    case StimulusKind::point:
      plan.source = std::make_unique<ListSource>(
          std::vector<Stimulus>{make_stimulus(formats, o.cos, o.n, o.rgb, "--cos/--n/--rgb")});
      plan.whole_operations = 1;
      plan.description = "--cos/--n/--rgb";
      break;
    case StimulusKind::input: {
      std::vector<Stimulus> all = read_stimuli_file(o.input_path, formats);
      if (o.shard.count > all.size())
        throw UsageError("--shard: N = " + std::to_string(o.shard.count) + " is outside the allowed range [1, " +
                         std::to_string(all.size()) + "] for '" + o.input_path + "' (" +
                         std::to_string(all.size()) + " operations; every shard at least one)");
      for (std::size_t i = 0; i < all.size(); ++i) {
        all[i].index = i;
        Result ops;  // the operation's codes, hashed like a result
        ops.reg1 = all[i].operands.cos;
        ops.reg9_pass1 = all[i].operands.n;
        for (int ch = 0; ch < 3; ++ch) ops.out[ch] = all[i].operands.rgb[ch];
        plan.input_checksum += result_hash(i, ops, 0);
      }
      plan.whole_operations = all.size();
      const auto [first, last] = shard_block(all.size(), o.shard);
      all.erase(all.begin() + static_cast<std::ptrdiff_t>(last), all.end());
      all.erase(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(first));
      plan.source = std::make_unique<ListSource>(std::move(all));
      plan.description = "--input " + o.input_path;
      break;
    }
    case StimulusKind::sweep: {
      const Stimulus any = make_stimulus(formats, 1.0, 1, o.rgb, "--rgb");
      plan.whole_operations = SweepSource(formats, any.rgb).size();
      plan.source = std::make_unique<SweepSource>(formats, any.rgb, o.shard);
      plan.description = "--sweep";
      break;
    }
    case StimulusKind::random:
      plan.whole_operations = o.random_count;
      plan.source = std::make_unique<RandomSource>(formats, o.random_count, o.seed, o.shard);
      plan.description =
          "--random " + std::to_string(o.random_count) + " --seed " + std::to_string(o.seed);
      break;
  }
  return plan;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// GTKWave's converter, found on PATH (empty: not installed).
std::string find_vcd2fst() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t at = 0; at <= dirs.size();) {
    const std::size_t colon = std::min(dirs.find(':', at), dirs.size());
    const std::filesystem::path candidate =
        std::filesystem::path(dirs.substr(at, colon - at).empty() ? "." : dirs.substr(at, colon - at)) /
        "vcd2fst";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    at = colon + 1;
  }
  return "";
}

/// The trace as FST: GTKWave's vcd2fst converts the VCD the run wrote (docs/performance.md
/// has its cost beside the VCD's), which is then removed.
void convert_to_fst(const std::string& vcd2fst, const std::string& vcd, const std::string& fst) {
  const pid_t child = ::fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    ::execl(vcd2fst.c_str(), "vcd2fst", vcd.c_str(), fst.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = -1;
  if (child > 0) ::waitpid(child, &status, 0);
  std::remove(vcd.c_str());
  if (child < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("vcd2fst could not convert the trace to '" + fst + "'");
}

std::string strip_vcd_suffix(const std::string& path) {
  const std::string suffix = ".vcd";
  if (path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0)
    return path.substr(0, path.size() - suffix.size());
  return path;
}

int run(const Options& o, std::ostream& out, std::ostream& err, const ResultTap& tap) {
  // Everything that can be wrong with the user's request is found here, before the
  // model is built: the stimuli (a file is read in full) and both output paths.
  const Formats formats(o.config.widths);
  try {  // a combination of policies the device refuses (ROM 38 or multiplier 39 would saturate)
    const Core check(o.config);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  Plan plan = make_plan(o, formats);
  if (o.trace_window && o.trace_first >= plan.source->size())
    throw UsageError("--trace-ops: FIRST = " + std::to_string(o.trace_first) +
                     " is outside the run's operations [0, " +
                     std::to_string(plan.source->size() - 1) + "]");
  if (!o.failure_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.failure_dir, ec);
    if (ec || !std::filesystem::is_directory(o.failure_dir))
      throw UsageError("--trace-failures: cannot make the directory '" + o.failure_dir + "'" +
                       (ec ? ": " + ec.message() : std::string()));
  }
  std::optional<AtomicOutputStream> output_file;
  if (!o.output_path.empty()) output_file.emplace(o.output_path, "--output");
  std::optional<AtomicOutputStream> partial_file;  // issue 25: partial.h
  if (!o.partial_path.empty()) partial_file.emplace(o.partial_path, "--partial");
  std::optional<AtomicFile> vcd_file;
  // A name ending in .fst asks for FST: the twins' Verilator writes it directly (their
  // models verilated with --trace-fst); the pin model writes a VCD that GTKWave's
  // vcd2fst converts when the run is over (docs/performance.md has both ways measured).
  const bool fst = ends_with(o.vcd_path, ".fst");
  const bool twin = o.model == Model::rtl || o.model == Model::rtl_sync;
  const bool convert = fst && !twin;
  const std::string vcd2fst = convert ? find_vcd2fst() : "";
  if (convert && vcd2fst.empty())
    throw UsageError("--vcd " + o.vcd_path + ": an FST trace needs GTKWave's vcd2fst (Debian "
                     "package gtkwave: scripts/setup.sh --gtkwave); give a .vcd name instead");
  // SystemC's VCD writer appends ".vcd" to the name it is given.
  if (!o.vcd_path.empty()) vcd_file.emplace(o.vcd_path, "--vcd", fst ? ".fst" : ".vcd");

  RunSettings settings;
  settings.model = o.variant.empty() ? o.model : Model::variant;  // issue 26: --variant
  settings.variant = o.variant;
  settings.config = o.config;
  settings.clock_period_ps = o.clock_period_ps;
  if (twin && fst) settings.twin_trace_suffix = ".fst";
  if (vcd_file)  // beside the temporary file: its name less .vcd (.fst: plus .trace, or less .fst)
    settings.vcd_base = convert ? vcd_file->temp_path() + ".trace"
                        : fst   ? vcd_file->temp_path().substr(0, vcd_file->temp_path().size() - 4)
                                : strip_vcd_suffix(vcd_file->temp_path());
  // The VCD an FST is converted from goes, whatever happens to the run.
  struct RemovedAtExit {
    std::string path;
    ~RemovedAtExit() {
      if (!path.empty()) std::remove(path.c_str());
    }
  } fst_source{convert ? settings.vcd_base + ".vcd" : std::string()};
  settings.real_views = o.real_views;
  // Issue 61: the TLM target's power trace, one CSV row per window.
  std::optional<AtomicOutputStream> power_file;
  settings.power_window_ps = o.power_window_ns * 1000;
  if (!o.power_csv_path.empty()) {
    power_file.emplace(o.power_csv_path, "--power-csv");
    power_file->stream() << "end_ns,power_mw,energy_pj\n";
    settings.power_window = [&power_file](double end_ns, double mw, double pj) {
      power_file->stream() << end_ns << ',' << mw << ',' << pj << '\n';
    };
  }
  double tlm_bus_pj = 0;
  settings.tlm_energy = [&tlm_bus_pj](const energy::EnergyTally& t) {
    tlm_bus_pj = t.read_pj + t.write_pj + t.clock_pj;
  };
  settings.trace_window = o.trace_window;
  settings.trace_first = o.trace_first;
  settings.trace_count = o.trace_count;
  // Failing operations of the batch just compared, to be replayed into their own files.
  std::vector<std::pair<std::uint64_t, std::string>> replays;
  if (!o.failure_dir.empty())
    settings.replays = [&replays] { return std::exchange(replays, {}); };

  std::ostream& report_stream = output_file ? output_file->stream() : out;
  const std::unique_ptr<Report> report = make_report(o.format, report_stream, err);
  RunDescription description;
  description.model = o.variant.empty() ? std::string(to_string(o.model)) : "variant " + o.variant;
  description.stimulus = plan.description;
  description.config = o.config;
  description.clock_period_ps = o.clock_period_ps;
  description.operations = plan.source->size();
  description.text_rows = o.stimulus != StimulusKind::sweep;
  RunDescription whole = description;  // what every shard of this run shares (partial.h)
  whole.operations = plan.whole_operations;
  if (!o.shard.whole()) description.stimulus += " --shard " + o.shard.text();
  report->begin(description);

  Scoreboard scoreboard = o.variant.empty() ? Scoreboard(o.config, latency_cycles(settings.model))
                                             : Scoreboard::for_variant(o.config);
  std::uint64_t index = 0;  // of the next result in the run
  // Issue 61: the operations' energy, from the results as the model gave them.
  const bool drawn = settings.model == Model::pin || settings.model == Model::rtl;
  energy::EnergyMeter meter(drawn ? energy::Calibration::drawn_device : energy::Calibration::synchronous_device,
                            Formats(o.config.widths));
  // Rows printed on the same terminal would land in the middle of the progress line.
  const bool rows_on_terminal = !output_file && &out == &std::cout && ::isatty(STDOUT_FILENO) == 1 &&
                                (o.format != OutputFormat::text || description.text_rows);
  Progress progress(std::cerr, plan.source->size(),
                    &err == &std::cerr && !rows_on_terminal && progress_wanted(o.quiet));
  std::vector<Stimulus> stimuli;  // the chunk in flight, aligned with its operands
  const OperandSource source = [&](std::vector<Operands>& chunk, std::size_t max) {
    chunk.clear();
    if (!plan.source->next(stimuli, max)) {
      // The pin model stops the kernel at the last rising edge of 35, before SystemC
      // writes that instant to the VCD: one more clock period (this runs in the pin
      // driver's thread) puts the last result's 35↑ into the waveform.
      if (pin_level(settings.model) && !settings.vcd_base.empty())
        sc_core::wait(sc_core::sc_time(static_cast<double>(o.clock_period_ps), sc_core::SC_PS));
      return false;
    }
    for (const Stimulus& s : stimuli) chunk.push_back(s.operands);
    return true;
  };
  const ResultSink sink = [&](const std::vector<Operands>&, const std::vector<Result>& results,
                              const std::vector<double>& cycles) {
    for (std::size_t i = 0; i < results.size(); ++i) {
      Result result = results[i];
      double measured = cycles[i];
      if (tap) tap(stimuli[i], result, measured);
      const Comparison c = scoreboard.compare(stimuli[i], result, measured);
      scoreboard.record(c);
      if (settings.model != Model::variant) meter.operation(stimuli[i].operands, result);
      report->row(c);
      if (!c.pass() && !o.failure_dir.empty()) {
        Summary& summary = scoreboard.summary();
        if (summary.failure_traces.size() < o.failure_max) {
          const std::string base =
              (std::filesystem::path(o.failure_dir) / ("op_" + std::to_string(index))).string();
          replays.emplace_back(index, base);
          summary.failure_traces.push_back(base + settings.twin_trace_suffix);
        } else {
          ++summary.failure_traces_left_out;
        }
      }
      ++index;
    }
    report->flush();
    progress.update(index);
    if (!report_stream) throw UsageError("cannot write the report (disk full?)");
  };

  const auto started = std::chrono::steady_clock::now();
  run_operations(settings, source, sink);
  progress.finish();
  if (settings.model != Model::variant) {
    scoreboard.summary().energy_pj = meter.tally(0).operation_pj;
    scoreboard.summary().energy_bus_pj = tlm_bus_pj;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  report->end(scoreboard.summary(), seconds);
  report_stream.flush();
  if (!report_stream) throw UsageError("cannot write the report (disk full?)");

  if (partial_file) {
    const ShardTiming timing{seconds, process_cpu_seconds()};
    partial_file->stream()
        << partial_json(partial_settings(whole, o.rgb, plan.input_checksum), o.shard,
                        scoreboard.summary(), timing)
               .dump(2, ' ', false, Json::error_handler_t::replace)
        << '\n';
    partial_file->commit();
  }
  if (output_file) output_file->commit();
  if (power_file) power_file->commit();
  if (vcd_file && convert) convert_to_fst(vcd2fst, settings.vcd_base + ".vcd", vcd_file->temp_path());
  if (vcd_file) vcd_file->commit();
  return scoreboard.summary().pass() ? exit_pass : exit_out_of_tolerance;
}

}  // namespace

int run_testbench(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                  const ResultTap& tap) {
  try {
    if (!args.empty() && args.front() == "--merge")  // issue 25: partial.h
      return run_merge(std::vector<std::string>(args.begin() + 1, args.end()), out, err);
    const Options options = parse_options(args);
    if (options.help) {
      out << help_text();
      return exit_pass;
    }
    if (options.version) {
      out << "specular_tb " << cli::version() << '\n';
      return exit_pass;
    }
    return run(options, out, err, tap);
  } catch (const UsageError& e) {
    err << "specular_tb: error: " << e.what() << "\n(specular_tb --help lists the options)\n";
    return exit_usage;
  } catch (const std::exception& e) {
    err << "specular_tb: internal error: " << e.what() << '\n';
    return exit_internal;
  }
}

}  // namespace tb
}  // namespace specular
