// The RTL twins as plain C++: the verilated device clocked edge by edge without the
// SystemC kernel, batches of operations as DeviceHarness runs them — RtlCycleModel (the
// drawn device) and RtlSyncCycleModel (the synchronous variant, the fast cycle model,
// fed through caller-owned arrays as a user's loop would: no allocation per chunk; the
// verilation specialised to the default device, or with allow_fixed false the general one).
#include <algorithm>

#include "bench.h"
#include "specular/twin/rtl_cycle_model.h"
#include "specular/twin/rtl_sync_cycle_model.h"

namespace specular_bench {
namespace {

/// Runs plan.ops operations through `model` in chunks of 4096; `run_chunk(model, batch,
/// out, count)` computes one chunk (batch.size() == count, out at least that long) with
/// the model's own batch call.
template <class Model, class RunChunk>
void measure_cycle_model(const Plan& plan, const std::string& name, bool stream, Model& model,
                         RunChunk run_chunk) {
  const specular::Core core;
  const std::vector<Operands> ring = random_operands(core, plan.seed);
  model.reset();
  constexpr std::size_t chunk = 4096;
  std::vector<Operands> batch(chunk);
  std::vector<Result> out(chunk);
  Checksum verify, work;
  double best = 1e300;
  std::uint64_t half_periods = 0;
  for (int rep = 0; rep < plan.repetitions; ++rep) {
    const std::uint64_t h0 = model.half_periods();
    const double t0 = now_seconds();
    for (std::size_t first = 0; first < plan.ops; first += chunk) {
      const std::size_t count = std::min(chunk, plan.ops - first);
      batch.resize(count);  // within its capacity: no allocation
      for (std::size_t j = 0; j < count; ++j)
        batch[j] = stream ? stream_operand(ring, first + j) : ring[(first + j) % ring_size];
      run_chunk(model, batch, out, count);
      for (std::size_t j = 0; j < count; ++j) {
        if (rep == 0 && first + j < plan.verify_ops) verify.add(out[j].out);
        work.add(out[j].out);
      }
    }
    best = std::min(best, now_seconds() - t0);
    half_periods = model.half_periods() - h0;
  }
  const double ops = static_cast<double>(plan.ops);
  print_figure(name + "_rate", ops / best / 1e6, "Mresults/s");
  print_figure(name + "_cycles_per_result", static_cast<double>(half_periods) / 2.0 / ops, "T");
  print_checksum(name + "_checksum", verify.value);
  print_checksum(name + "_work", work.value);
  print_figure(name + "_peak_memory", static_cast<double>(peak_memory_kb()), "kB");
}

}  // namespace

void measure_rtl_cycle_model(const Plan& plan, const std::string& name, bool stream,
                             bool allow_fixed) {
  specular::RtlCycleModel model(specular::Config{}, allow_fixed);
  print_figure(name + "_fixed", model.fixed() ? 1.0 : 0.0, "bool");
  measure_cycle_model(plan, name, stream, model,
                      [](specular::RtlCycleModel& m, std::vector<Operands>& batch,
                         std::vector<Result>& out, std::size_t /*count: batch.size()*/) {
                        m.run_batch(batch, out);
                      });
}

void measure_rtl_sync_cycle_model(const Plan& plan, const std::string& name, bool stream,
                                  bool allow_fixed) {
  specular::RtlSyncCycleModel model(specular::Config{}, allow_fixed);
  // 1: the verilation specialised to the default device (docs/rtl.md), 0: the general one.
  print_figure(name + "_fixed", model.fixed() ? 1.0 : 0.0, "bool");
  measure_cycle_model(plan, name, stream, model,
                      [](specular::RtlSyncCycleModel& m, std::vector<Operands>& batch,
                         std::vector<Result>& out, std::size_t count) {
                        m.run_batch(batch.data(), out.data(), count);
                      });
}

}  // namespace specular_bench
