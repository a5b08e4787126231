#include "options.h"

#include <algorithm>
#include <map>
#include <set>

#include <fstream>

#include "cli.h"
#include "input.h"
#include "parse_values.h"
#include "specular/variants/variant.h"
#include "usage_error.h"

namespace specular {
namespace tb {

namespace {

/// The registered design variants, "patent, ...", for messages and --help.
std::string variant_list() {
  std::string list;
  for (const std::string& name : variants::variant_names()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

/// Every option that takes a value, with what the value must be (for "missing value").
const std::map<std::string, std::string>& valued_options() {
  static const std::map<std::string, std::string> options = {
      {"--cos", "a number in [0, 1]"},
      {"--n", "an integer in [1, 1000]"},
      {"--rgb", "R,G,B, each an integer in [0, 255]"},
      {"--input", "a CSV file of lines cos,n,r,g,b"},
      {"--random", "a count in [1, 100000000]"},
      {"--seed", "an unsigned 64-bit integer"},
      {"--model", "one of: " + model_names()},
      {"--policy", "one of: patent, energy, none, device-energy"},
      {"--constants", "one of: patent, minimax-half, minimax"},
      {"--saturation", "one of: clamp, literal"},
      {"--width", "NAME=VALUE, NAME one of: " + width_names()},
      {"--clock-period", "a time, a multiple of 4 ps in [4 ps, 1 ms], e.g. 10ns"},
      {"--vcd", "a file name"},
      {"--format", "one of: text, csv, json, jsonl"},
      {"--output", "a file name"},
      {"--shard", "I/N, 0 <= I < N (e.g. 0/4)"},          // issue 25: shard.h
      {"--partial", "a file name (JSON partial result)"},  // issue 25: partial.h
      {"--trace-ops", "FIRST:COUNT, operations FIRST .. FIRST+COUNT-1 (from 0), COUNT >= 1"},
      {"--trace-failures", "a directory"},
      {"--trace-failures-max", "a count in [1, 1000]"},
      {"--variant", "a design variant's name, one of: " + variant_list()},  // issue 26
      {"--power-csv", "a file name"},                                            // issue 61
      {"--power-window", "a count of nanoseconds in [1, 1000000000]"},
  };
  return options;
}

std::string with_option(const std::string& option, const std::string& message) {
  return option + ": " + message;
}

/// One option's value, converted and checked (the conversions of parse_values.h, the
/// policy names of format.h); every message starts with the option's name.
void apply_value(const std::string& option, const std::string& value, Options& o, std::string& rgb_value) {
  try {
    if (option == "--cos") {
      o.cos = parse_cos(value);
    } else if (option == "--n") {
      o.n = parse_integer(value, "n", "[1, 1000]");
      check_n(o.n);
    } else if (option == "--rgb") {
      rgb_value = value;  // checked below, at the widths every --width has set
    } else if (option == "--input") {
      if (value.empty()) throw UsageError("the file name is empty");
      o.input_path = value;
    } else if (option == "--sweep") {
      // no value
    } else if (option == "--real-views") {
      o.real_views = true;
    } else if (option == "--quiet") {
      o.quiet = true;
    } else if (option == "--trace-ops") {
      const std::size_t colon = value.find(':');
      if (colon == std::string::npos)
        throw UsageError("'" + value + "' is not FIRST:COUNT (operations FIRST .. FIRST+COUNT-1, "
                         "counted from 0, e.g. 734511:2)");
      o.trace_first = parse_unsigned64(value.substr(0, colon), "FIRST");
      o.trace_count = parse_unsigned64(value.substr(colon + 1), "COUNT");
      if (o.trace_count < 1)
        throw UsageError("COUNT = " + value.substr(colon + 1) + " is outside the allowed range [1, " +
                         std::to_string(~std::uint64_t{0}) + "]");
      o.trace_window = true;
    } else if (option == "--trace-failures") {
      if (value.empty()) throw UsageError("the directory name is empty");
      o.failure_dir = value;
    } else if (option == "--power-csv") {  // issue 61: the TLM target's power trace
      if (value.empty()) throw UsageError("the file name is empty");
      o.power_csv_path = value;
    } else if (option == "--power-window") {
      const std::string range = "[1, 1000000000] (ns)";
      const long long ns = parse_integer(value, "NS", range);
      if (ns < 1 || ns > 1000000000) throw UsageError("NS = " + value + " is outside the allowed range " + range);
      o.power_window_ns = static_cast<std::uint64_t>(ns);
    } else if (option == "--trace-failures-max") {
      const std::string range = "[1, " + std::to_string(failure_traces_max) + "]";
      const long long count = parse_integer(value, "N", range);
      if (count < 1 || static_cast<unsigned long long>(count) > failure_traces_max)
        throw UsageError("N = " + value + " is outside the allowed range " + range);
      o.failure_max = static_cast<std::size_t>(count);
    } else if (option == "--random") {
      const std::string range = "[1, " + std::to_string(random_count_max) + "]";
      const long long count = parse_integer(value, "N", range);
      if (count < 1 || static_cast<unsigned long long>(count) > random_count_max)
        throw UsageError("N = " + value + " is outside the allowed range " + range);
      o.random_count = static_cast<std::size_t>(count);
    } else if (option == "--seed") {
      o.seed = parse_unsigned64(value, "seed");
    } else if (option == "--model") {
      o.model = parse_model(value);
    } else if (option == "--policy") {
      o.config.normalisation = parse_normalisation(value);
    } else if (option == "--saturation") {
      o.config.saturation = parse_saturation(value);
    } else if (option == "--constants") {
      o.config.constants = parse_constants(value);
    } else if (option == "--width") {
      const std::size_t equals = value.find('=');
      if (equals == std::string::npos)
        throw UsageError("'" + value + "' is not NAME=VALUE (NAME one of: " + width_names() + ")");
      const std::string name = value.substr(0, equals);
      const long long bits = parse_integer(value.substr(equals + 1), name, "[0, 63]");
      if (bits < 0 || bits > 63)
        throw UsageError(name + " = " + value.substr(equals + 1) +
                         " is outside the allowed range [0, 63]");
      set_width(o.config.widths, name, static_cast<int>(bits));
    } else if (option == "--clock-period") {
      o.clock_period_ps = parse_clock_period_ps(value);
    } else if (option == "--vcd") {
      if (value.empty()) throw UsageError("the file name is empty");
      o.vcd_path = value;
    } else if (option == "--format") {
      o.format = parse_output_format(value);
    } else if (option == "--output") {
      if (value.empty()) throw UsageError("the file name is empty");
      o.output_path = value;
    } else if (option == "--shard") {  // issue 25
      o.shard = parse_shard(value);
    } else if (option == "--partial") {
      if (value.empty()) throw UsageError("the file name is empty");
      o.partial_path = value;
    } else if (option == "--variant") {  // issue 26
      const auto names = variants::variant_names();
      if (std::find(names.begin(), names.end(), value) == names.end())
        throw UsageError("unknown variant '" + value + "' (known: " + variant_list() + ")");
      o.variant = value;
    }
  } catch (const UsageError& e) {
    const std::string message = e.what();
    // Messages from the parsers already start with the option's name.
    if (message.rfind(option, 0) == 0) throw;
    throw UsageError(with_option(option, message));
  } catch (const std::exception& e) {  // range checks and policy names of format.h
    throw UsageError(with_option(option, e.what()));
  }
}

/// Declares every option of specular_tb on `app`; each value goes through apply_value.
void add_options(specular::cli::Command& app, Options& o, std::string& rgb_value) {
  const auto valued = [&](const std::string& name, const std::string& type, const std::string& help) {
    return app
        .add_option_function<std::string>(
            name, [&o, &rgb_value, name](const std::string& v) { apply_value(name, v, o, rgb_value); }, help)
        ->type_name(type);
  };
  const auto flag = [&](const std::string& name, bool& target, const std::string& help) {
    return app.add_flag(name, target, help)->disable_flag_override();
  };
  app.add_flag("--sweep", "every n in 1..1000 x a cos grid (below); 1021 values x 1000 n")
      ->disable_flag_override()
      ->group("Stimulus (exactly one)");
  valued("--cos", "C", "cos lambda in [0, 1], quantised to register 1 (U1.16); with --n")
      ->group("Stimulus (exactly one)");
  valued("--n", "N", "the exponent, an integer in [1, 1000]; with --cos")->group("Stimulus (exactly one)");
  valued("--rgb", "R,G,B", "the light's intensities, integers in [0, 255] (default 255,255,255); with --cos/--n or --sweep")
      ->group("Stimulus (exactly one)");
  valued("--input", "FILE",
         "CSV lines cos,n,r,g,b ('#' comments, blank lines and a header line cos,n,r,g,b allowed)")
      ->group("Stimulus (exactly one)");
  valued("--random", "N",
         "N computations (N in [1, 100000000]): cos codes drawn uniformly in [0, 2^16], n in 1..1000, "
         "R, G, B in 0..255, with a 64-bit Mersenne Twister; a seed gives the same draws on every platform")
      ->group("Stimulus (exactly one)");
  valued("--seed", "S", "--random's seed, an unsigned 64-bit integer (default 1)")->group("Stimulus (exactly one)");

  const std::string device = "Model and device";
  valued("--model", "pin|core|tlm|rtl|rtl-sync",
         "pin (default): the pin-level SystemC netlist, driven on pins 17-35\n"
         "(reset 29, load registers, start on 27, read 24-26 at the rising edge\n"
         "of 35); cycles are measured.\n"
         "rtl: the RTL twin (rtl/device/ verilated into SystemC) under the same\n"
         "harness, protocol checker and options as pin.\n"
         "rtl-sync: the synchronous variant (one clock, start and loads sampled\n"
         "at its rising edge; docs/rtl.md) under the same harness with its\n"
         "protocol; cycles must be 2.\n"
         "core: the kernel-free bit-accurate core (same arithmetic, no kernel,\n"
         "much faster); its cycles column is the spec's 2.5 periods, the model's\n"
         "annotated latency, not a measurement.\n"
         "tlm: the TLM-2.0 lt target (docs/tlm.md) through its registers from an\n"
         "initiator thread (1 us quantum); cycles = the START write's annotated\n"
         "delay in periods of --clock-period.")
      ->group(device);
  valued("--policy", "patent|energy|none|device-energy",
         "ROM 38 contents: 2pi/(n+2) (default), (n+2)/(2pi), 1, or 1/I(n), I(n) the equation-6 integral "
         "of the device's own lobe")
      ->group(device);
  valued("--saturation", "clamp|literal", "second-pass result: saturate at 0 (default) or keep sign")->group(device);
  valued("--constants", "patent|minimax-half|minimax",
         "pins 20 (a), 19 (h) and ROM 38's scale s: the patent's 1, 1/2, 1 (default); minimax-half: "
         "a = 1.148987, h = 1/2, s = 0.953465 (max |s*A - cos^n| 0.0734); minimax: a = 0.373026, "
         "h = 41/256, s = 1.664246 (0.0398). The approx column is register 9, which peaks at 1/s")
      ->group(device);
  app.add_option_function<std::vector<std::string>>(
         "--width",
         [&o, &rgb_value](const std::vector<std::string>& values) {
           for (const std::string& v : values) apply_value("--width", v, o, rgb_value);
         },
         "a bus width other than docs/design.md's, once per width (e.g. --width rom5_word_bits=20 "
         "--width reg9_frac_bits=16, the RTL's other verilated set); NAME one of: " + width_names())
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false)
      ->group(device);
  valued("--clock-period", "T",
         "pin 28's period, e.g. 10ns (default), 2500ps, 1us; a multiple of 4 ps (inputs change a "
         "quarter period before an edge) in [4 ps, 1 ms]")
      ->group(device);
  valued("--variant", "NAME",
         "a design variant's C++ model instead of the device (issue 26, docs/design_space.md); NAME one "
         "of: " + variant_list() + ". The same stimuli, reports and shards; the lobe is the norm column, "
         "out_*_ref = norm_exact*R, G, B, approx is not measured (no register 9), cycles 0 (no clock). "
         "Report only: every computation passes (each variant's bound: docs/variants/NAME.md). Not with "
         "--model, --vcd, --trace-ops, --trace-failures, --clock-period")
      ->group(device);

  const std::string output = "Output";
  valued("--format", "text|csv|json|jsonl",
         "text (default): a table and a summary (a sweep prints the summary only); csv: one row per "
         "computation, summary on standard error; json: {settings, results[], summary}; jsonl: JSON "
         "Lines, {tool, settings}, one line per result, {summary}: readable while the run goes (rows "
         "are written after each batch of 4096; on standard output, as --output renames its file only "
         "when the run is complete)")
      ->group(output);
  valued("--output", "FILE",
         "write there instead of standard output (written to a temporary file and renamed when complete)")
      ->group(output);
  valued("--vcd", "FILE",
         "pin model: write a VCD of every pin and net (time unit 1 ps); open it\n"
         "with waveforms/specular.gtkw, which shows the buses as real numbers\n"
         "(GTKWave's fixed-point display). A sweep's VCD is huge (1.6 KB an\n"
         "operation): trace a window of it with --trace-ops, or its failures\n"
         "with --trace-failures.\n"
         "rtl model: Verilator's VCD of the RTL's own nets, named by reference\n"
         "number; open it with waveforms/specular_rtl.gtkw (rtl-sync:\n"
         "waveforms/specular_rtl_sync.gtkw).\n"
         "A name ending in .fst gives GTKWave's compressed FST (rtl, rtl-sync:\n"
         "written by Verilator; pin: converted by GTKWave's vcd2fst when the\n"
         "run ends).\n"
         "tlm model: the target's view, whole run: STATUS's busy, done and\n"
         "error, done_irq, the power (mW, over --power-window) and the energy\n"
         "so far (pJ); open it with waveforms/specular_tlm.gtkw.")
      ->group(output);
  valued("--power-csv", "FILE",
         "tlm model: the power trace, a row per window: its end (ns), the mean power over it (mW), "
         "the energy so far (pJ)")
      ->group(output);
  valued("--power-window", "NS", "tlm model: the power trace's window, 1 ns to 1 s (default 1000 ns)")
      ->group(output);
  valued("--trace-ops", "FIRST:COUNT",
         "with --vcd: trace only operations FIRST .. FIRST+COUNT-1 (counted from 0, as in the CSV's "
         "rows): the file holds the instants from the first one's inputs to the last one's 35 rising, "
         "at the run's own times; the others run untraced")
      ->group(output);
  valued("--trace-failures", "DIR",
         "pin, rtl, rtl-sync: each operation out of tolerance is run again, with the one before it, into "
         "DIR/op_INDEX.vcd (INDEX from 0; times are the replay's); the report names them")
      ->group(output);
  valued("--trace-failures-max", "N", "at most N such files (default 10, N in [1, 1000])")->group(output);
  flag("--quiet", o.quiet,
       "no progress line on standard error (it is shown only when standard error is a terminal)")
      ->group(output);
  flag("--real-views", o.real_views,
       "with --vcd: also trace cos, register 9, K(n), K*A and pins 24-26 as real-valued *_real "
       "variables, for viewers that cannot show a bus as fixed point (about 1.3x the trace time)")
      ->group(output);
  valued("--shard", "I/N",
         "run shard I (0-based) of N: --sweep by n ((n-1) mod N = I), --random and --input by contiguous "
         "blocks of operations; the N shards together run exactly the unsharded operations")
      ->group(output);
  valued("--partial", "FILE",
         "also write this run's partial result (JSON: settings, commit, shard, summary with the "
         "maxima's places, checksum, timing); specular_tb --merge FILE... [--format text|json] "
         "[--output FILE] [--partial FILE] merges every shard's partial into the unsharded run's "
         "report (refusing a missing, duplicated or mismatched shard)")
      ->group(output);
  app.set_config("--config",
                 "read options from FILE, TOML or INI: a line NAME = VALUE per long option (cos = 0.5, "
                 "sweep = true, width = [\"rom5_word_bits=20\", \"reg9_frac_bits=16\"]); the command "
                 "line's options win")
      ->type_name("FILE");
}

/// Where `option` is set in the configuration file `path` ("FILE:LINE"), "" if not found:
/// CLI11 names the option, the line is found here.
std::string config_place(const std::string& path, const std::string& option) {
  std::ifstream in(path);
  const std::string key = option.substr(2);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string t = trim(line);
    if (t.rfind(key, 0) == 0 && t.size() > key.size() &&
        trim(t.substr(key.size())).rfind('=', 0) == 0)
      return path + ":" + std::to_string(number);
  }
  return "";
}

/// Checks what no single option can: which go together, which exclude each other.
void check_combination(const specular::cli::Command& app, Options& o, const std::string& rgb_value) {
  const auto given = [&](const std::string& name) { return app.count(name) > 0; };
  try {
    o.config.widths.validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--width: ") + e.what());
  }
  if (given("--rgb")) {
    const Formats widths_set(o.config.widths);
    try {
      o.rgb = parse_rgb_triplet(rgb_value, widths_set, "");
      static const char* channels[3] = {"R", "G", "B"};
      for (int ch = 0; ch < 3; ++ch) check_rgb(widths_set, o.rgb[ch], channels[ch]);
    } catch (const UsageError& e) {
      const std::string message = e.what();
      if (message.rfind("--rgb", 0) == 0) throw;
      throw UsageError(with_option("--rgb", message));
    } catch (const std::exception& e) {
      throw UsageError(with_option("--rgb", e.what()));
    }
  }

  // Exactly one source of computations.
  const bool point = given("--cos") || given("--n");
  const int sources = (point ? 1 : 0) + static_cast<int>(given("--input")) +
                      static_cast<int>(given("--sweep")) + static_cast<int>(given("--random"));
  if (sources == 0)
    throw UsageError(
        "nothing to compute: give --cos C --n N [--rgb R,G,B], --input FILE, --sweep or --random N");
  if (sources > 1)
    throw UsageError(
        "choose one of: --cos/--n (one point), --input FILE, --sweep, --random N");
  if (point) {
    o.stimulus = StimulusKind::point;
    if (!given("--cos")) throw UsageError("--n needs --cos C as well (cos in [0, 1])");
    if (!given("--n")) throw UsageError("--cos needs --n N as well (n in [1, 1000])");
  } else if (given("--input")) {
    o.stimulus = StimulusKind::input;
  } else if (given("--sweep")) {
    o.stimulus = StimulusKind::sweep;
  } else {
    o.stimulus = StimulusKind::random;
  }
  if (given("--rgb") && (o.stimulus == StimulusKind::input || o.stimulus == StimulusKind::random))
    throw UsageError("--rgb applies to --cos/--n and --sweep only (the file or the random draw gives R, G, B)");
  if (given("--seed") && o.stimulus != StimulusKind::random)
    throw UsageError("--seed applies to --random N only");
  if (!o.vcd_path.empty() && !pin_level(o.model) && o.model != Model::tlm)
    throw UsageError("--vcd needs --model pin, rtl, rtl-sync or tlm (the " + std::string(to_string(o.model)) +
                     " model has no signals to trace)");
  if (o.model == Model::tlm && !o.vcd_path.empty() && (o.trace_window || o.real_views))
    throw UsageError(std::string(o.trace_window ? "--trace-ops" : "--real-views") +
                     " needs a pin-level model (--model tlm's VCD is the target's view: STATUS, "
                     "done_irq and the power, over the whole run)");
  if (!o.power_csv_path.empty() && o.model != Model::tlm)
    throw UsageError("--power-csv needs --model tlm (the TLM target carries the power trace; the " +
                     std::string(to_string(o.model)) + " model reports its energy in the summary)");
  if (given("--power-window") && o.model != Model::tlm)
    throw UsageError("--power-window needs --model tlm (the window of its power trace)");
  if (!o.power_csv_path.empty() && (o.power_csv_path == o.output_path || o.power_csv_path == o.vcd_path))
    throw UsageError("--power-csv names the same file as --output or --vcd: '" + o.power_csv_path + "'");
  if (o.real_views && (o.model == Model::rtl || o.model == Model::rtl_sync))
    throw UsageError("--real-views needs --model pin (the " + std::string(to_string(o.model)) +
                     " model's VCD is Verilator's, of the RTL's own nets as codes: "
                     "waveforms/specular_rtl.gtkw and specular_rtl_sync.gtkw show them as reals)");
  if (o.real_views && o.vcd_path.empty())
    throw UsageError("--real-views needs --vcd FILE (the views exist only in a trace)");
  if (o.trace_window && o.vcd_path.empty())
    throw UsageError("--trace-ops needs --vcd FILE (the window is written there)");
  if (!o.failure_dir.empty() && !pin_level(o.model))
    throw UsageError("--trace-failures needs --model pin, rtl or rtl-sync (the " +
                     std::string(to_string(o.model)) + " model has no signals to trace)");
  if (!o.failure_dir.empty() && !o.vcd_path.empty())
    throw UsageError("--trace-failures and --vcd: give one (a failing operation's waveform is a "
                     "file of its own in the directory; --vcd --trace-ops FIRST:COUNT traces a window)");
  if (given("--trace-failures-max") && o.failure_dir.empty())
    throw UsageError("--trace-failures-max needs --trace-failures DIR");
  if (!o.vcd_path.empty() && !o.output_path.empty() && o.vcd_path == o.output_path)
    throw UsageError("--vcd and --output name the same file '" + o.vcd_path + "'");
  // issue 25: sharding (shard.h); an input file's size is checked once it is read.
  if (given("--shard") && o.stimulus == StimulusKind::point)
    throw UsageError("--shard applies to --sweep, --random N and --input FILE only (one point is not split)");
  if (o.stimulus == StimulusKind::sweep && o.shard.count > n_max - n_min + 1)
    throw UsageError("--shard: N = " + std::to_string(o.shard.count) +
                     " is outside the allowed range [1, 1000] for --sweep (split by n)");
  if (o.stimulus == StimulusKind::random && o.shard.count > o.random_count)
    throw UsageError("--shard: N = " + std::to_string(o.shard.count) + " is outside the allowed range [1, " +
                     std::to_string(o.random_count) + "] for --random " + std::to_string(o.random_count) +
                     " (every shard at least one computation)");
  if (!o.variant.empty()) {  // issue 26: the variant's C++ model, kernel-free
    for (const char* option : {"--model", "--vcd", "--trace-ops", "--trace-failures", "--clock-period"})
      if (given(option))
        throw UsageError(std::string("--variant runs the variant's C++ model (no clock, no signals): ") +
                         option + " does not apply");
    try {
      (void)variants::make_variant(o.variant, o.config);
    } catch (const std::invalid_argument& e) {  // a configuration the variant is not built for
      throw UsageError("--variant " + o.variant + ": " + e.what());
    }
  }
  if (!o.partial_path.empty() && (o.partial_path == o.output_path || o.partial_path == o.vcd_path))
    throw UsageError("--partial names the same file as --output or --vcd: '" + o.partial_path + "'");
}

const char* const description =
    R"(specular_tb: drives the specular colour intensity device of UA 59965 U (Fig. 1-3)
through its pins as an SoC would, and compares every result with the
double-precision reference.

The runs:
  specular_tb --cos C --n N [--rgb R,G,B]   one computation (RGB default 255,255,255)
  specular_tb --input FILE                  CSV lines cos,n,r,g,b
  specular_tb --sweep [--rgb R,G,B]         every n in 1..1000 x a cos grid (below)
  specular_tb --random N [--seed S]         N computations drawn at random (seed 1)
  specular_tb --merge FILE... [--format text|json] [--output FILE] [--partial FILE]
                                            every shard's partial merged into the
                                            unsharded run's report
  specular_tb --config FILE [OPTIONS]       the options from a TOML or INI file

The --sweep grid: cos = every multiple of 2^-9 in [0, 1] (0 and 1 included) plus
the 512 codes just below 1 (1 - k*2^-16, k = 1..512), where the error is largest:
1021 values x 1000 n = 1,021,000 computations.
)";

const char* const footer =
    R"(Fields per computation (csv/json): cos, n, r, g, b, cos_q (register 1 as a real),
  approx (register 9 after pass 2), approx_ref, norm (multiplier 39), norm_ref,
  norm_exact (K(n)*cos_q^n), out_r, out_g, out_b (pins 24-26), out_r_ref, out_g_ref,
  out_b_ref, cycles (start on 27 to the rising edge of 35, in clock periods), hex
  codes at their bus widths (two's complement): reg1_hex, reg9_pass1_hex,
  reg9_pass2_hex, pin24_hex, pin25_hex, pin26_hex; pass (1/0).

Tolerances: |approx - approx_ref| <= 2^-10; |norm - norm_ref| <= 2^-10*max(1,K);
  |out - out_ref| <= 2^-10*max(1,K)*I + 1 output LSB; cycles = 2.5.

Exit status: 0 every computation within tolerance; 1 some computation out of
  tolerance; 2 bad option, value, configuration file, input file or output path
  (nothing is run); 3 internal error.)";

/// The command line, declared: house_rules, the texts, every option.
void declare(specular::cli::Command& app, Options& o, std::string& rgb_value) {
  app.description(description);
  cli::house_rules(app, footer);
  add_options(app, o, rgb_value);
}

}  // namespace

Options parse_options(const std::vector<std::string>& args) {
  specular::cli::Command app{"", "specular_tb"};
  Options o;
  std::string rgb_value;
  declare(app, o, rgb_value);
  try {
    switch (cli::parse(app, args)) {
      case cli::Parsed::help:
        o.help = true;
        return o;
      case cli::Parsed::version:
        o.version = true;
        return o;
      case cli::Parsed::run:
        break;
    }
  } catch (const cli::CommandLineError& e) {
    std::string message = e.what();
    const auto see = message.find(" (see --help)");  // run_testbench says where to look
    if (see != std::string::npos) message.erase(see, 13);
    // A value missing at the end of the line: say what it must be.
    const auto needs = message.find(" needs a value");
    if (needs != std::string::npos && message.rfind("option ", 0) == 0) {
      const auto known = valued_options().find(message.substr(7, needs - 7));
      if (known != valued_options().end()) message = message.substr(0, needs) + " needs a value: " + known->second;
    }
    throw UsageError(message);
  } catch (const UsageError& e) {  // a value refused by apply_value
    const std::string message = e.what();
    const std::string config = app.config_file();
    const std::string option = message.substr(0, message.find(':'));
    const bool on_line = std::any_of(args.begin(), args.end(), [&](const std::string& a) {
      return a == option || a.rfind(option + "=", 0) == 0;
    });
    if (config.empty() || on_line || option.rfind("--", 0) != 0) throw;
    const std::string place = config_place(config, option);
    throw UsageError((place.empty() ? config : place) + ": " + message);
  }
  check_combination(app, o, rgb_value);
  return o;
}

std::string help_text() {
  specular::cli::Command app{"", "specular_tb"};
  Options o;
  std::string rgb_value;
  declare(app, o, rgb_value);
  return app.help();
}

}  // namespace tb
}  // namespace specular
