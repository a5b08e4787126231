// specular_tb's row path with the core model (issue 27): the core, the scoreboard's
// comparison with the double reference and the CSV or JSON writer, into a stream that
// discards the bytes, over the same ring of inputs as the core's own figure; the best
// of several repetitions counts. core_csv_vs_core (main.cpp) is the ratio in one run.
#include <algorithm>
#include <ostream>
#include <streambuf>

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
}  // namespace

void measure_rows(const Plan& plan, const std::string& name, bool json) {
  namespace tb = specular::tb;
  const specular::Core core;
  const std::vector<Operands> ring = random_operands(core, plan.seed);
  std::vector<tb::Stimulus> stimuli(ring_size);
  for (std::size_t i = 0; i < ring_size; ++i) {
    tb::Stimulus& s = stimuli[i];
    s.operands = ring[i];
    s.cos = core.formats().cos.to_real(ring[i].cos);
    s.n = static_cast<unsigned>(ring[i].n);
    for (int ch = 0; ch < 3; ++ch) s.rgb[ch] = static_cast<unsigned>(ring[i].rgb[ch]);
  }
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

}  // namespace specular_bench
