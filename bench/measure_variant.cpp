// The design variants' C++ models (issue 26, variant.h), each timed over the core's
// ring of inputs as measure_core is: the figures the parent divides by the core's rate
// (variant_NAME_vs_core), the patent's device first.
#include <algorithm>

#include "bench.h"
#include "specular/variants/variant.h"

namespace specular_bench {

void measure_variant(const Plan& plan, const std::string& variant_name) {
  const specular::Core core;
  const std::vector<Operands> ring = random_operands(core, plan.seed);
  const auto variant = specular::variants::make_variant(variant_name);
  const std::string name = "variant_" + variant_name;

  Checksum random_set;  // the patent's equals core_checksum; the others are their own
  for (std::size_t i = 0; i < plan.verify_ops; ++i) random_set.add(variant->run(ring[i & (ring_size - 1)]).out);

  std::uint64_t work = 0;
  double best = 1e300;
  for (int rep = 0; rep < plan.repetitions; ++rep) {
    const double t0 = now_seconds();
    for (std::size_t i = 0; i < plan.ops; ++i) {
      const specular::variants::VariantResult r = variant->run(ring[i & (ring_size - 1)]);
      work += static_cast<std::uint64_t>(r.out[0] + r.out[1] + r.out[2]);
    }
    best = std::min(best, now_seconds() - t0);
  }
  print_figure(name + "_rate", static_cast<double>(plan.ops) / best / 1e6, "Mresults/s");
  print_checksum(name + "_checksum", random_set.value);
  print_checksum(name + "_work", work);
  print_figure(name + "_peak_memory", static_cast<double>(peak_memory_kb()), "kB");
}

}  // namespace specular_bench
