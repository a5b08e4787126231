// specular_bench: how fast each model of the device runs, as results per second and
// as a ratio to std::pow(c, n) in double measured in the same run.
//
//   specular_bench [--all] [--quick] [--repetitions N]
//                                        every model, each in its own child process, N
//                                        interleaved repetitions (default 5; --quick 1):
//                                        every figure as median [min..max], every target
//                                        met, not met or within noise (summary.h)
//   specular_bench --model NAME [...]    one model in this process (what a child runs)
//   specular_bench --variants [...]      std::pow, the core and the design variants'
//                                        C++ models only (variant_NAME_vs_core)
//   specular_bench --list                the model names
//
// Output: one `name: value unit` line per figure; lines starting with '#' are notes.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench.h"
#include "cli.h"
#include "summary.h"
#include "specular/systemc.h"
#include "specular/variants/variant.h"
#include "usage_error.h"

namespace specular_bench {
namespace {

/// One model the parent runs in a child: its name, how to measure it, and how many
/// operations (full run, --quick run) and repetitions it gets. Counts are chosen so a
/// full run stays under a minute on a 2-core machine and each figure takes ≥ 0.2 s.
struct Model {
  std::string name;
  std::function<void(const Plan&)> measure;
  std::size_t full_ops;
  std::size_t quick_ops;
  int repetitions;
  std::string what;
  bool ratio = true;  ///< print <name>_vs_pow (not for the yardstick's second run, growth runs)
};

/// The checksum prefix every model shares; no model runs fewer operations in --quick.
constexpr std::size_t verify_ops = 4096;

std::vector<Model> listed_models();

/// Every model: the list below with each registered design variant's C++ model
/// (variant_NAME, issue 26) after the core, so new variants need no line here.
const std::vector<Model>& models() {
  static const std::vector<Model> all = [] {
    std::vector<Model> list = listed_models();
    auto at = std::find_if(list.begin(), list.end(), [](const Model& m) { return m.name == "core"; }) + 1;
    for (const std::string& variant : specular::variants::variant_names()) {
      at = list.insert(at, Model{"variant_" + variant,
                                 [variant](const Plan& p) { measure_variant(p, variant); },
                                 8'000'000, 200'000, 5,
                                 "design variant " + variant + "'s C++ model (variant.h), over the core's inputs"}) + 1;
    }
    return list;
  }();
  return all;
}

/// Whether `name` is a design variant's model (variant_NAME).
bool is_variant_model(const std::string& name) { return name.rfind("variant_", 0) == 0; }

std::vector<Model> listed_models() {
  const std::vector<Model> all = {
      {"pow", [](const Plan& p) { measure_pow(p, "pow"); }, 8'000'000, 200'000, 5, "std::pow(c, n) in double: the yardstick"},
      {"core", measure_core, 16'000'000, 200'000, 5, "bit-accurate core (Core::run)"},
      // specular_tb --model core --format csv/json per row: core, comparison, writer.
      {"core_csv", [](const Plan& p) { measure_rows(p, "core_csv", false); }, 2'000'000, 50'000, 3,
       "specular_tb's CSV rows with the core model (core + comparison + writer)"},
      {"core_json", [](const Plan& p) { measure_rows(p, "core_json", true); }, 2'000'000, 50'000, 3,
       "specular_tb's JSON rows with the core model (core + comparison + writer)"},
      {"pin_vcd_off",
       [](const Plan& p) { measure_pin(p, "pin_vcd_off", false, Trace::off); },
       400'000, 8192, 1, "pin-level device, random n/RGB every result (3 T), no trace"},
      {"pin_stream",
       [](const Plan& p) { measure_pin(p, "pin_stream", true, Trace::off); },
       400'000, 8192, 1, "pin-level device, n/RGB held per 256 results (2 T), no trace"},
      // The RTL twin under the same harness, the harness's floor (a device that only
      // keeps time), and the twin as plain C++ without the kernel (docs/rtl.md).
      {"rtl_vcd_off",
       [](const Plan& p) { measure_pin(p, "rtl_vcd_off", false, Trace::off, PinDevice::rtl); },
       400'000, 8192, 1, "RTL twin (verilated) under the pin harness, as pin_vcd_off (3 T)"},
      {"rtl_stream",
       [](const Plan& p) { measure_pin(p, "rtl_stream", true, Trace::off, PinDevice::rtl); },
       400'000, 8192, 1, "RTL twin under the pin harness, as pin_stream (2 T)"},
      {"rtl_sync_vcd_off",
       [](const Plan& p) { measure_pin(p, "rtl_sync_vcd_off", false, Trace::off, PinDevice::rtl_sync); },
       400'000, 8192, 1, "synchronous RTL variant under the pin harness, as pin_vcd_off (3 T)"},
      {"rtl_sync_stream",
       [](const Plan& p) { measure_pin(p, "rtl_sync_stream", true, Trace::off, PinDevice::rtl_sync); },
       400'000, 8192, 1, "synchronous RTL variant under the pin harness, as pin_stream (2 T)"},
      {"floor_vcd_off",
       [](const Plan& p) { measure_pin(p, "floor_vcd_off", false, Trace::off, PinDevice::floor); },
       400'000, 8192, 1, "the harness with a device that only keeps time (3 T): the floor"},
      {"floor_stream",
       [](const Plan& p) { measure_pin(p, "floor_stream", true, Trace::off, PinDevice::floor); },
       400'000, 8192, 1, "the harness's floor, streaming (2 T)"},
      {"rtl_cpp",
       [](const Plan& p) { measure_rtl_cycle_model(p, "rtl_cpp", false); },
       4'000'000, 100'000, 3, "RTL twin as plain C++ (RtlCycleModel), random n/RGB (3 T)"},
      {"rtl_cpp_stream",
       [](const Plan& p) { measure_rtl_cycle_model(p, "rtl_cpp_stream", true); },
       8'000'000, 200'000, 3, "RTL twin as plain C++, n/RGB held per 256 results (2 T)"},
      {"rtl_general_cpp_stream",
       [](const Plan& p) { measure_rtl_cycle_model(p, "rtl_general_cpp_stream", true, false); },
       4'000'000, 200'000, 3, "RTL twin as plain C++, general verilation, streaming (2 T)"},
      // The synchronous variant (rtl/device/specular_device_sync.v) as plain C++: the fast
      // cycle model (docs/rtl.md).
      {"rtl_sync_cpp",
       [](const Plan& p) { measure_rtl_sync_cycle_model(p, "rtl_sync_cpp", false); },
       8'000'000, 200'000, 3, "synchronous RTL variant as plain C++ (RtlSyncCycleModel), random n/RGB (3 T)"},
      {"rtl_sync_cpp_stream",
       [](const Plan& p) { measure_rtl_sync_cycle_model(p, "rtl_sync_cpp_stream", true); },
       16'000'000, 200'000, 3, "synchronous RTL variant as plain C++, n/RGB held per 256 results (2 T)"},
      // The same through the general verilation (configuration as inputs), beside the
      // one specialised to the default device that rtl_sync_cpp* run (issue 28).
      {"rtl_sync_general_cpp_stream",
       [](const Plan& p) { measure_rtl_sync_cycle_model(p, "rtl_sync_general_cpp_stream", true, false); },
       8'000'000, 200'000, 3, "synchronous RTL variant as plain C++, general verilation, streaming (2 T)"},
      {"pin_vcd_on",
       [](const Plan& p) { measure_pin(p, "pin_vcd_on", false, Trace::vcd); },
       100'000, 4096, 1, "pin-level device as pin_vcd_off, every pin and net to VCD (specular_tb --vcd)"},
      {"pin_vcd_real_views",
       [](const Plan& p) { measure_pin(p, "pin_vcd_real_views", false, Trace::vcd_real_views); },
       100'000, 4096, 1, "as pin_vcd_on, plus the *_real views (specular_tb --vcd --real-views)"},
      {"tlm_lt_quantum",
       [](const Plan& p) { measure_tlm(p, "tlm_lt_quantum", {false, false, sc_core::sc_time(1, sc_core::SC_US), true}); },
       4'000'000, 20'000, 3, "TLM lt target, SpecularDriver::compute_burst per result (fast path: OPERANDS + RESULTS bursts), 1 us quantum"},
      {"tlm_lt_quantum_regs",
       [](const Plan& p) { measure_tlm(p, "tlm_lt_quantum_regs", {false, false, sc_core::sc_time(1, sc_core::SC_US)}); },
       2'000'000, 20'000, 3, "TLM lt target, SpecularDriver::compute per result (one register per transaction), 1 us quantum"},
      {"tlm_lt",
       [](const Plan& p) { measure_tlm(p, "tlm_lt", {false, false, sc_core::SC_ZERO_TIME}); },
       500'000, 8192, 3, "TLM lt target, compute per result, no temporal decoupling"},
      {"tlm_pin",
       [](const Plan& p) { measure_tlm(p, "tlm_pin", {true, false, sc_core::sc_time(1, sc_core::SC_US)}); },
       200'000, 4096, 1, "TLM pin target (transactor + netlist), compute per result"},
      {"tlm_rtl_quantum",
       [](const Plan& p) { measure_tlm(p, "tlm_rtl_quantum", {false, false, sc_core::sc_time(1, sc_core::SC_US), true, true}); },
       1'000'000, 20'000, 3, "TLM rtl target (RTL twin clocked in b_transport), compute_burst per result, 1 us quantum"},
      {"tlm_rtl_batch",
       [](const Plan& p) { measure_tlm(p, "tlm_rtl_batch", {false, true, sc_core::sc_time(1, sc_core::SC_US), false, true}); },
       2'000'000, 50'000, 3, "TLM rtl target, BATCH_COS bursts of 256 sharing n/RGB, 1 us quantum"},
      {"tlm_lt_batch",
       [](const Plan& p) { measure_tlm(p, "tlm_lt_batch", {false, true, sc_core::sc_time(1, sc_core::SC_US)}); },
       8'000'000, 100'000, 5, "TLM lt target, BATCH_COS bursts of 256 sharing n/RGB, 1 us quantum"},
      // The energy model's cost (issue 61): the same two lt runs with it switched on.
      {"tlm_lt_quantum_energy",
       [](const Plan& p) {
         measure_tlm(p, "tlm_lt_quantum_energy",
                     {false, false, sc_core::sc_time(1, sc_core::SC_US), true, false, true});
       },
       1'000'000, 20'000, 3, "tlm_lt_quantum with the energy model on (set_energy_model(true))"},
      {"tlm_lt_batch_energy",
       [](const Plan& p) {
         measure_tlm(p, "tlm_lt_batch_energy", {false, true, sc_core::sc_time(1, sc_core::SC_US), false, false, true});
       },
       1'000'000, 100'000, 5, "tlm_lt_batch with the energy model on"},
      {"tlm_pin_batch",
       [](const Plan& p) { measure_tlm(p, "tlm_pin_batch", {true, true, sc_core::sc_time(1, sc_core::SC_US)}); },
       200'000, 4096, 1, "TLM pin target, BATCH_COS bursts of 256 sharing n/RGB"},
      // How cost grows with the number of results: the same pin model, 1k to 100k
      // results (as many in --quick: growth is the point), with peak memory each.
      {"pin_growth_1k",
       [](const Plan& p) { measure_pin(p, "pin_growth_1k", false, Trace::off); },
       1'000, 1'000, 1, "pin_vcd_off for 1 000 results (growth)", false},
      {"pin_growth_10k",
       [](const Plan& p) { measure_pin(p, "pin_growth_10k", false, Trace::off); },
       10'000, 10'000, 1, "pin_vcd_off for 10 000 results (growth)", false},
      {"pin_growth_100k",
       [](const Plan& p) { measure_pin(p, "pin_growth_100k", false, Trace::off); },
       100'000, 100'000, 1, "pin_vcd_off for 100 000 results (growth)", false},
      {"vcd_growth_10k",
       [](const Plan& p) { measure_pin(p, "vcd_growth_10k", false, Trace::vcd); },
       10'000, 10'000, 1, "pin_vcd_on for 10 000 results (growth of the trace)", false},
      // The yardstick again, last: the machine's load drifts during a run; ratios use
      // the faster of the two pow runs, so a quiet start cannot flatter a model.
      {"pow_end", [](const Plan& p) { measure_pow(p, "pow_end"); }, 8'000'000, 200'000, 5, "std::pow(c, n) again, after every model", false},
  };
  return all;
}

/// Models run only by name (--model), not by --all.
const std::vector<Model>& extra_models() {
  static const std::vector<Model> extra = {
      // The same rows through nlohmann-json (issue 25): a measurement of the
      // choice docs/farm.md records (specular_bench --model core_json_nlohmann[_serializer]).
      {"core_json_nlohmann", [](const Plan& p) { measure_rows_nlohmann(p, "core_json_nlohmann", false); },
       2'000'000, 50'000, 3, "JSON rows written by nlohmann-json's dump() (core + comparison + writer)"},
      {"core_json_nlohmann_serializer",
       [](const Plan& p) { measure_rows_nlohmann(p, "core_json_nlohmann_serializer", true); }, 2'000'000, 50'000,
       3, "JSON rows written by nlohmann-json's serializer kept across rows"},
  };
  return extra;
}

const Model* find_model(const std::string& name) {
  for (const Model& m : models())
    if (m.name == name) return &m;
  for (const Model& m : extra_models())
    if (m.name == name) return &m;
  return nullptr;
}

/// One figure line of a child: `name: value unit` (value's text kept for checksums).
struct Figure {
  double value = 0;
  std::string text;
  std::string unit;
};
/// One repetition's figures, by name.
using Round = std::map<std::string, Figure>;

/// Runs one child (`specular_bench --model NAME ...`) and keeps its figures in `round`
/// (`order` gets every name the first time it is seen). Lines that are not figures
/// (SystemC's reports, errors) are echoed as notes tagged with `tag`. Returns false
/// when the child failed.
bool run_child(const std::vector<std::string>& args, const std::string& tag, Round& round,
               std::vector<std::string>& order) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return false;
  std::fflush(stdout);
  const pid_t pid = ::fork();
  if (pid < 0) return false;
  if (pid == 0) {
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv("/proc/self/exe", argv.data());
    std::perror("specular_bench: exec");
    std::_Exit(127);
  }
  ::close(pipe_fds[1]);
  FILE* from_child = ::fdopen(pipe_fds[0], "r");
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, from_child) != nullptr) {
    std::string line(buffer);
    if (!line.empty() && line.back() == '\n') line.pop_back();
    const std::size_t colon = line.find(": ");
    const std::string name = colon == std::string::npos ? "" : line.substr(0, colon);
    // Figure names are lower-case identifiers; anything else (SystemC's reports) is text.
    if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos) {
      std::printf("# %s: %s\n", tag.c_str(), line.c_str());
      continue;
    }
    const std::string rest = line.substr(colon + 2);
    const std::size_t space = rest.find(' ');
    Figure f;
    f.text = rest.substr(0, space);
    f.unit = space == std::string::npos ? "" : rest.substr(space + 1);
    f.value = std::strtod(rest.c_str(), nullptr);
    if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
    round[name] = f;
  }
  std::fclose(from_child);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/// The performance targets (docs/performance.md), each named by the figure it judges.
const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"core_vs_pow", true, 3.0, "bit-accurate core, results/s over std::pow's"},
      {"tlm_lt_quantum_vs_pow", true, 0.25, "TLM lt target, 1 us quantum, over std::pow"},
      {"tlm_lt_batch_vs_pow", true, 0.7, "TLM lt target, BATCH_COS bursts, over std::pow"},
      // The figure: n, R, G, B change every result (3 T) ...
      {"pin_vcd_off_vs_pow", true, 0.01, "pin-level device, new n/RGB every result (3 T), over std::pow"},
      // ... and beside it one material streaming at 2 T.
      {"pin_stream_vs_pow", true, 0.01, "pin-level device, n/RGB held per 256 results (2 T), over std::pow"},
      // The synchronous variant's fast cycle model (issue 19): 0.25x std::pow and
      // 10 M results/s, streaming one material.
      {"rtl_sync_cpp_stream_vs_pow", true, 0.25, "synchronous RTL variant as plain C++, streaming (2 T), over std::pow"},
      {"rtl_sync_cpp_stream_rate", true, 10.0, "synchronous RTL variant as plain C++, streaming (2 T), M results/s"},
      // Issue 28: the synchronous twin under the SystemC harness, 3x the netlist.
      {"rtl_sync_vs_pin", true, 3.0, "synchronous RTL variant under the pin harness (3 T) over the SystemC netlist"},
      {"rtl_sync_stream_vs_pin_stream", true, 3.0, "synchronous RTL variant under the pin harness, streaming (2 T), over the netlist"},
      {"vcd_slowdown", false, 6.0, "pin-level device without VCD over with VCD (how much slower tracing is)"},
      // Issue 61: the energy model slows the lt target by at most 5 %.
      {"energy_slowdown_quantum", false, 1.05, "TLM lt, 1 us quantum: energy model off over on"},
      {"energy_slowdown_batch", false, 1.05, "TLM lt, BATCH_COS bursts: energy model off over on"},
  };
   return all;
}

/// The figures the parent derives from one repetition's children: the yardstick (the
/// faster of that repetition's pow and pow_end), every ratio to it, the VCD's cost.
void add_ratios(Round& round, std::vector<std::string>& order) {
  const auto add = [&](const std::string& name, double value, const std::string& unit) {
    if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
    round[name] = Figure{value, "", unit};
  };
  const auto rate = [&](const std::string& name) {
    const auto it = round.find(name + "_rate");
    return it == round.end() ? 0.0 : it->second.value;
  };
  const double pow_rate = std::max(rate("pow"), rate("pow_end"));
  if (pow_rate <= 0) return;
  add("pow_yardstick_rate", pow_rate, "Mevals/s");
  for (const Model& m : models())
    if (m.name != "pow" && m.ratio && rate(m.name) > 0) add(m.name + "_vs_pow", rate(m.name) / pow_rate, "x");
  // Each design variant's C++ model over the patent's Core, in the same repetition.
  for (const Model& m : models())
    if (is_variant_model(m.name) && rate(m.name) > 0 && rate("core") > 0)
      add(m.name + "_vs_core", rate(m.name) / rate("core"), "x");
  if (rate("core") > 0 && rate("core_csv") > 0) {
    add("core_csv_vs_core", rate("core_csv") / rate("core"), "x");
    add("core_json_vs_core", rate("core_json") / rate("core"), "x");
  }
  // Issue 61: what the energy model costs the lt target (off over on: 1.05 is 5 % slower).
  if (rate("tlm_lt_quantum") > 0 && rate("tlm_lt_quantum_energy") > 0)
    add("energy_slowdown_quantum", rate("tlm_lt_quantum") / rate("tlm_lt_quantum_energy"), "x");
  if (rate("tlm_lt_batch") > 0 && rate("tlm_lt_batch_energy") > 0)
    add("energy_slowdown_batch", rate("tlm_lt_batch") / rate("tlm_lt_batch_energy"), "x");
  if (rate("pin_vcd_on") > 0) add("vcd_slowdown", rate("pin_vcd_off") / rate("pin_vcd_on"), "x");
  if (rate("pin_vcd_real_views") > 0)
    add("vcd_real_views_slowdown", rate("pin_vcd_off") / rate("pin_vcd_real_views"), "x");
  // The RTL twin and the harness's floor against the netlist, under the same harness.
  if (rate("pin_vcd_off") > 0 && rate("rtl_vcd_off") > 0) {
    add("rtl_vs_pin", rate("rtl_vcd_off") / rate("pin_vcd_off"), "x");
    add("floor_vs_pin", rate("floor_vcd_off") / rate("pin_vcd_off"), "x");
  }
  if (rate("pin_vcd_off") > 0 && rate("rtl_sync_vcd_off") > 0)
    add("rtl_sync_vs_pin", rate("rtl_sync_vcd_off") / rate("pin_vcd_off"), "x");
  if (rate("pin_stream") > 0 && rate("rtl_sync_stream") > 0)
    add("rtl_sync_stream_vs_pin_stream", rate("rtl_sync_stream") / rate("pin_stream"), "x");
  if (rate("pin_stream") > 0 && rate("rtl_stream") > 0) {
    add("rtl_stream_vs_pin_stream", rate("rtl_stream") / rate("pin_stream"), "x");
    add("floor_stream_vs_pin_stream", rate("floor_stream") / rate("pin_stream"), "x");
  }
}

/// Every model gives the core's results to the bit on the same inputs (in one repetition).
bool bit_exact(const Round& round, bool quick) {
  const auto core = round.find("core_checksum");
  const auto stream = round.find("core_stream_checksum");
  if (core == round.end() || stream == round.end()) return false;
  bool exact = true;
  for (const Model& m : models()) {
    if (m.name == "pow" || m.name == "pow_end" || m.name == "core") continue;
    if (m.name.rfind("floor_", 0) == 0) continue;  // computes nothing, by design
    // A variant computes its own results; the patent's device must be the core's.
    if (is_variant_model(m.name) && m.name != "variant_patent") continue;
    const bool streamed = m.name.find("_stream") != std::string::npos ||
                          m.name.find("_batch") != std::string::npos;
    const auto it = round.find(m.name + "_checksum");
    // A growth run shorter than the shared prefix hashes fewer results: not comparable.
    if (it == round.end() || (quick ? m.quick_ops : m.full_ops) < verify_ops) continue;
    if (it->second.text != (streamed ? stream : core)->second.text) {
      std::printf("# %s differs from the core on the first %zu results\n", m.name.c_str(), verify_ops);
      exact = false;
    }
  }
  return exact;
}

/// `name: median unit [min..max]`; a bool holds only if it held in every repetition,
/// a checksum is printed when every repetition gave the same one.
void print_summary(const std::string& name, const std::vector<Figure>& samples) {
  const std::string& unit = samples.front().unit;
  if (unit == "hex") {
    bool same = true;
    for (const Figure& f : samples) same = same && f.text == samples.front().text;
    std::printf("%s: %s hex%s\n", name.c_str(), same ? samples.front().text.c_str() : "differs",
                same ? "" : " (between repetitions)");
    return;
  }
  std::vector<double> values;
  for (const Figure& f : samples) values.push_back(f.value);
  const Spread s = spread_of(values);
  if (unit == "bool") {
    std::printf("%s: %d bool\n", name.c_str(), s.min != 0 ? 1 : 0);
    return;
  }
  std::printf("%s: %.4g %s [%.4g..%.4g]\n", name.c_str(), s.median, unit.c_str(), s.min, s.max);
}

/// --variants: only the yardstick, the core and the design variants' models.
bool in_variants_run(const std::string& name) {
  return name == "pow" || name == "core" || name == "pow_end" || is_variant_model(name);
}

int run_all(bool quick, int repetitions, std::uint64_t seed, const std::string& vcd_stem,
            bool variants_only = false) {
  std::printf("# specular_bench%s: seed %llu, every model in its own process, %d interleaved repetition%s\n",
              quick ? " --quick (smoke test: too few operations for stable figures)" : "",
              static_cast<unsigned long long>(seed), repetitions, repetitions == 1 ? "" : "s");
  std::printf("# a repetition runs every model once, in this order (best of N: timed N times in its process):\n");
  for (const Model& m : models())
    if (!variants_only || in_variants_run(m.name))
      std::printf("#   %s: %s; %zu operations, best of %d\n", m.name.c_str(), m.what.c_str(),
                  quick ? m.quick_ops : m.full_ops, quick ? 1 : m.repetitions);
  std::fflush(stdout);

  std::vector<std::string> order;
  std::map<std::string, std::vector<Figure>> samples;
  std::vector<std::string> failed;
  bool exact = true;
  for (int rep = 1; rep <= repetitions; ++rep) {
    std::printf("# repetition %d of %d\n", rep, repetitions);
    std::fflush(stdout);
    Round round;
    for (const Model& m : models()) {
      if (variants_only && !in_variants_run(m.name)) continue;
      const std::size_t ops = quick ? m.quick_ops : m.full_ops;
      const int reps = quick ? 1 : m.repetitions;
      if (!run_child({"specular_bench", "--model", m.name, "--ops", std::to_string(ops), "--reps",
                      std::to_string(reps), "--seed", std::to_string(seed), "--verify",
                      std::to_string(verify_ops), "--vcd", vcd_stem},
                     m.name + " (repetition " + std::to_string(rep) + ")", round, order))
        failed.push_back(m.name + " (repetition " + std::to_string(rep) + ")");
    }
    add_ratios(round, order);
    exact = bit_exact(round, quick) && exact;
    for (const auto& [name, figure] : round) samples[name].push_back(figure);
  }

  std::printf("# figures: name: median unit [min..max] over the %d repetitions; ratios to std::pow use\n"
              "# each repetition's own yardstick (the faster of its pow and pow_end)\n",
              repetitions);
  for (const std::string& name : order) print_summary(name, samples[name]);

  // Reported, never a failure: a busy machine slows models and yardstick differently.
  std::printf("# targets: target_<figure>: verdict (median [min..max], bound). Verdicts: met = every\n"
              "# repetition meets the bound; not met = none does; within noise = the spread straddles it\n");
  VerdictCount count;
  for (const Target& t : targets()) {
    const auto it = samples.find(t.figure);
    if (it == samples.end()) continue;
    std::vector<double> values;
    for (const Figure& f : it->second) values.push_back(f.value);
    const Spread s = spread_of(values);
    const Verdict v = judge(s, t.at_least, t.bound);
    count.add(v);
    // In the figure's own unit: ratios are "x", rates "Mresults/s".
    const char* unit = it->second.front().unit.c_str();
    std::printf("target_%s: %s (%.4g %s [%.4g..%.4g], bound %s %g %s: %s)\n", t.figure.c_str(),
                to_string(v), s.median, unit, s.min, s.max, t.at_least ? ">=" : "<=", t.bound, unit,
                t.what.c_str());
  }
  std::printf("targets_met: %d of %d (%d not met, %d within noise)\n", count.met, count.total(),
              count.not_met, count.within_noise);

  print_figure("bit_exact", exact ? 1 : 0, "bool");
  for (const std::string& name : failed) std::printf("# FAILED: %s\n", name.c_str());
  return failed.empty() && exact ? 0 : 1;
}

/// The command line, declared (run_support/cli.h).
struct BenchOptions {
  std::string model;
  bool all = false, quick = false, list = false, variants_only = false;
  std::size_t ops = 0;
  int repetitions = 0;  // 0: the default, 5 (1 with --quick)
};

void add_options(specular::cli::Command& app, BenchOptions& o, Plan& plan) {
  namespace cli = specular::cli;
  app.add_flag("--all", o.all, "every model in its own child process, with the ratios to std::pow (the default)");
  app.add_flag("--variants", o.variants_only,
               "only std::pow, the core and each design variant's C++ model (variant_NAME_vs_core)");
  app.add_flag("--quick", o.quick, "a smoke test with few operations");
  app.add_option("--repetitions", o.repetitions,
                 "every model runs N times, interleaved, and each figure is printed as its median "
                 "[min..max]; a target is met, not met or within noise (default 5, --quick 1)")
      ->type_name("N")
      ->check(cli::integer_in(1, 100));
  app.add_flag("--list", o.list, "the model names");
  app.add_option("--model", o.model, "one model in this process (what a child runs)")->type_name("NAME");
  const auto count = [&](const std::string& name, auto& target, long long max, const std::string& help) {
    app.add_option(name, target, help)->type_name("N")->check(cli::integer_in(1, max));
  };
  count("--ops", o.ops, 1000000000000LL, "--model: operations (default the model's)");
  count("--reps", plan.repetitions, 1000000, "--model: repetitions in this process");
  count("--seed", plan.seed, std::numeric_limits<long long>::max(), "the operands' seed");
  count("--verify", plan.verify_ops, 1000000000000LL, "--model: operations compared with the core");
  app.add_option("--vcd", plan.vcd_path,
                 "where the traced model writes STEM.vcd (deleted after measuring its size unless --keep-vcd)")
      ->type_name("STEM");
  app.add_flag("--keep-vcd", plan.keep_vcd, "keep the traced model's VCD");
}

int bench_main(const BenchOptions& o, Plan plan) {
  const std::string& model = o.all ? std::string() : o.model;
  const bool quick = o.quick, list = o.list, variants_only = o.variants_only;
  const std::size_t ops = o.ops;
  const int repetitions = o.repetitions;
  if (list) {
    for (const Model& m : models()) std::cout << m.name << ": " << m.what << "\n";
    return 0;
  }
  if (model.empty())
    return run_all(quick, repetitions != 0 ? repetitions : (quick ? 1 : 5), plan.seed, plan.vcd_path,
                   variants_only);

  const Model* m = find_model(model);
  if (m == nullptr) {
    std::string names;
    for (const Model& each : models()) names += " " + each.name;
    throw specular::tb::UsageError("--model: unknown model " + model + "; choose one of:" + names);
  }
  plan.ops = ops != 0 ? ops : (quick ? m->quick_ops : m->full_ops);
  if (plan.verify_ops == 0 || plan.verify_ops > plan.ops) plan.verify_ops = std::min(verify_ops, plan.ops);
  // SystemC's infos ("stopped by user", the VCD timescale) would mix into the figures.
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  m->measure(plan);
  return 0;
}

}  // namespace
}  // namespace specular_bench

int sc_main(int argc, char** argv) {
  specular::cli::Command app{"specular_bench: results per second of every model, each in its own process; prints one\n"
                             "`name: value unit` line per figure (docs/performance.md).\n"
                             "  specular_bench [--all | --variants] [--quick] [--repetitions N] [--seed N] [--vcd STEM]\n"
                             "  specular_bench --model NAME [--ops N] [--reps N] [--seed N] [--verify N] [--vcd STEM] [--keep-vcd]\n"
                             "  specular_bench --list",
                             "specular_bench"};
  specular::cli::house_rules(app, "Exit status: 0 done, 1 a model failed or differs from the core, 2 bad usage.");
  specular_bench::BenchOptions options;
  specular_bench::Plan plan;
  plan.vcd_path = std::string(std::getenv("TMPDIR") != nullptr ? std::getenv("TMPDIR") : "/tmp") +
                  "/specular_bench_" + std::to_string(::getpid());
  specular_bench::add_options(app, options, plan);
  return specular::cli::run(app, argc, argv, [&] {
    try {
      return specular_bench::bench_main(options, plan);
    } catch (const specular::tb::UsageError&) {
      throw;  // cli::run: exit 2
    } catch (const std::exception& e) {
      std::cerr << "specular_bench: " << e.what() << "\n";
      return 2;
    }
  });
}

int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);  // keep stdout to figure lines
  return sc_core::sc_elab_and_sim(argc, argv);
}
