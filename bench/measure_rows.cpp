// specular_tb's row path with the core model (issue 27): the core, the scoreboard's
// comparison with the double reference and the CSV or JSON writer, into a stream that
// discards the bytes, over the same ring of inputs as the core's own figure; the best
// of several repetitions counts. core_csv_vs_core (main.cpp) is the ratio in one run.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <ostream>
#include <streambuf>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "report.h"
#include "scoreboard.h"

namespace specular_bench {

namespace {
/// Counts the bytes and drops them: the figure is the writer's, not the disk's.
class CountingBuf : public std::streambuf {
 public:
  std::size_t bytes = 0;

 protected:
  std::streamsize xsputn(const char*, std::streamsize n) override {
    bytes += static_cast<std::size_t>(n);
    return n;
  }
  int overflow(int ch) override {
    ++bytes;
    return ch;
  }
};
/// The testbench's stimuli for a ring of operands (both row writers time the same rows).
std::vector<specular::tb::Stimulus> stimulus_ring(const specular::Core& core,
                                                  const std::vector<Operands>& ring) {
  std::vector<specular::tb::Stimulus> stimuli(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) {
    specular::tb::Stimulus& s = stimuli[i];
    s.operands = ring[i];
    s.cos = core.formats().cos.to_real(ring[i].cos);
    s.n = static_cast<unsigned>(ring[i].n);
    for (int ch = 0; ch < 3; ++ch) s.rgb[ch] = static_cast<unsigned>(ring[i].rgb[ch]);
  }
  return stimuli;
}

}  // namespace

void measure_rows(const Plan& plan, const std::string& name, bool json) {
  namespace tb = specular::tb;
  const specular::Core core;
  const std::vector<Operands> ring = random_operands(core, plan.seed);
  const std::vector<tb::Stimulus> stimuli = stimulus_ring(core, ring);
  double best = 1e300;
  std::size_t bytes = 0;
  for (int rep = 0; rep < plan.repetitions; ++rep) {
    CountingBuf sink;
    std::ostream out(&sink), side(&sink);
    tb::Scoreboard scoreboard(core.config());
    const auto report = tb::make_report(json ? tb::OutputFormat::json : tb::OutputFormat::csv, out, side);
    tb::RunDescription run;
    run.model = "core";
    run.stimulus = "bench";
    run.operations = plan.ops;
    report->begin(run);
    const double t0 = now_seconds();
    for (std::size_t i = 0; i < plan.ops; ++i) {
      const std::size_t k = i & (ring_size - 1);
      const tb::Comparison c = scoreboard.compare(stimuli[k], core.run(ring[k]), tb::spec_latency_cycles);
      scoreboard.record(c);
      report->row(c);
      if ((i & 4095) == 4095) report->flush();
    }
    report->flush();
    best = std::min(best, now_seconds() - t0);
    bytes = sink.bytes;
  }
  print_figure(name + "_rate", static_cast<double>(plan.ops) / best / 1e6, "Mrows/s");
  print_figure(name + "_bytes_per_row", static_cast<double>(bytes) / static_cast<double>(plan.ops), "B");
}

/// The same rows (the same keys, in the same order, the same values) written with
/// nlohmann-json instead of the buffered writer (issue 25: "rows move to nlohmann-json"),
/// measured the same way: one ordered_json row object built once and its values
/// overwritten in place per row (no key lookup), then either dump() per row (the public interface: a new string
/// each time) or (`serializer`) the library's own serializer kept across rows, writing
/// into one string that goes to the stream every 4096 rows. The core and the comparison
/// are in both figures, as in core_json.
void measure_rows_nlohmann(const Plan& plan, const std::string& name, bool serializer) {
  namespace tb = specular::tb;
  using Json = nlohmann::ordered_json;
  const specular::Core core;
  const specular::Formats& f = core.formats();
  const std::vector<Operands> ring = random_operands(core, plan.seed);
  const std::vector<tb::Stimulus> stimuli = stimulus_ring(core, ring);
  const auto hex = [](std::uint64_t v, int bits) {
    char text[24];
    std::snprintf(text, sizeof text, "%0*llx", (bits + 3) / 4, static_cast<unsigned long long>(v));
    return std::string(text);
  };
  double best = 1e300;
  std::size_t bytes = 0;
  for (int rep = 0; rep < plan.repetitions; ++rep) {
    CountingBuf sink;
    std::ostream out(&sink);
    tb::Scoreboard scoreboard(core.config());
    Json row = {{"cos", 0.0}, {"n", 0}, {"r", 0}, {"g", 0}, {"b", 0}, {"cos_q", 0.0}, {"approx", 0.0},
                {"approx_ref", 0.0}, {"norm", 0.0}, {"norm_ref", 0.0}, {"norm_exact", 0.0}, {"out_r", 0.0},
                {"out_g", 0.0}, {"out_b", 0.0}, {"out_r_ref", 0.0}, {"out_g_ref", 0.0}, {"out_b_ref", 0.0},
                {"cycles", 0.0}, {"reg1_hex", ""}, {"reg9_pass1_hex", ""}, {"reg9_pass2_hex", ""},
                {"pin24_hex", ""}, {"pin25_hex", ""}, {"pin26_hex", ""}, {"pass", true}};
    // Each value's place, found once: a row overwrites them without a key lookup.
    std::vector<Json*> slot;
    for (auto& item : row.items()) slot.push_back(&item.value());
    std::string buffer;
    nlohmann::detail::serializer<Json> writer(nlohmann::detail::output_adapter<char>(buffer), ' ');
    const double t0 = now_seconds();
    for (std::size_t i = 0; i < plan.ops; ++i) {
      const std::size_t k = i & (ring_size - 1);
      const tb::Comparison c = scoreboard.compare(stimuli[k], core.run(ring[k]), tb::spec_latency_cycles);
      scoreboard.record(c);
      *slot[0] = c.stimulus.cos;
      *slot[1] = c.stimulus.n;
      *slot[2] = c.stimulus.rgb[0];
      *slot[3] = c.stimulus.rgb[1];
      *slot[4] = c.stimulus.rgb[2];
      *slot[5] = c.ref.cos_q;
      *slot[6] = c.approx;
      *slot[7] = c.ref.approx_ref;
      *slot[8] = c.norm;
      *slot[9] = c.ref.norm_ref;
      *slot[10] = c.ref.norm_exact;
      *slot[11] = c.out[0];
      *slot[12] = c.out[1];
      *slot[13] = c.out[2];
      *slot[14] = c.ref.out_ref[0];
      *slot[15] = c.ref.out_ref[1];
      *slot[16] = c.ref.out_ref[2];
      *slot[17] = c.cycles;
      *slot[18] = hex(c.result.reg1, f.cos.width());
      *slot[19] = hex(c.result.reg9_pass1, f.reg9.width());
      *slot[20] = hex(c.result.reg9_pass2, f.reg9.width());
      *slot[21] = hex(c.result.out[0], f.out.width());
      *slot[22] = hex(c.result.out[1], f.out.width());
      *slot[23] = hex(c.result.out[2], f.out.width());
      *slot[24] = c.pass();
      buffer += i == 0 ? "\n    " : ",\n    ";
      if (serializer) writer.dump(row, false, false, 0);
      else buffer += row.dump();
      if ((i & 4095) == 4095) {
        out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        buffer.clear();
      }
    }
    out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    best = std::min(best, now_seconds() - t0);
    bytes = sink.bytes;
  }
  print_figure(name + "_rate", static_cast<double>(plan.ops) / best / 1e6, "Mrows/s");
  print_figure(name + "_bytes_per_row", static_cast<double>(bytes) / static_cast<double>(plan.ops), "B");
}

}  // namespace specular_bench
