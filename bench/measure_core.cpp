// The yardstick (std::pow in double) and the bit-accurate core, each timed over the
// same ring of inputs; the best of several repetitions counts.
#include <algorithm>
#include <cmath>

#include "bench.h"

namespace specular_bench {

void measure_pow(const Plan& plan, const std::string& name) {
  const specular::Core core;
  const std::vector<Operands> ring = random_operands(core, plan.seed);
  // cos λ as the real number register 1 holds, n as a double: what a shader would call.
  std::vector<double> cosines(ring_size), exponents(ring_size);
  for (std::size_t i = 0; i < ring_size; ++i) {
    cosines[i] = core.formats().cos.to_real(ring[i].cos);
    exponents[i] = static_cast<double>(ring[i].n);
  }
  double best = 1e300, work = 0.0;
  for (int rep = 0; rep < plan.repetitions; ++rep) {
    const double t0 = now_seconds();
    for (std::size_t i = 0; i < plan.ops; ++i) {
      const std::size_t k = i & (ring_size - 1);
      work += std::pow(cosines[k], exponents[k]);
    }
    best = std::min(best, now_seconds() - t0);
  }
  print_figure(name + "_rate", static_cast<double>(plan.ops) / best / 1e6, "Mevals/s");
  print_figure(name + "_work", work, "sum");  // printed so the optimiser must compute it
  print_figure(name + "_peak_memory", static_cast<double>(peak_memory_kb()), "kB");
}

void measure_core(const Plan& plan) {
  const specular::Core core;
  const std::vector<Operands> ring = random_operands(core, plan.seed);

  // The reference checksums every other model is compared with (untimed).
  Checksum random_set, stream_set;
  for (std::size_t i = 0; i < plan.verify_ops; ++i) {
    random_set.add(core.run(ring[i & (ring_size - 1)]).out);
    stream_set.add(core.run(stream_operand(ring, i)).out);
  }

  // The timed loop only sums the outputs (a hash's multiply chain would cost as much
  // as the core itself); the sum is printed, so the optimiser must compute every result.
  std::uint64_t work = 0;
  double best = 1e300;
  for (int rep = 0; rep < plan.repetitions; ++rep) {
    const double t0 = now_seconds();
    for (std::size_t i = 0; i < plan.ops; ++i) {
      const Result r = core.run(ring[i & (ring_size - 1)]);
      work += static_cast<std::uint64_t>(r.out[0] + r.out[1] + r.out[2]);
    }
    best = std::min(best, now_seconds() - t0);
  }
  print_figure("core_rate", static_cast<double>(plan.ops) / best / 1e6, "Mresults/s");
  // 1: the default widths, run with compile-time formats (core.h DefaultFormats).
  print_figure("core_default_formats", core.uses_default_formats() ? 1 : 0, "bool");
  print_checksum("core_checksum", random_set.value);
  print_checksum("core_stream_checksum", stream_set.value);
  print_checksum("core_work", work);
  print_figure("core_peak_memory", static_cast<double>(peak_memory_kb()), "kB");
}

}  // namespace specular_bench
