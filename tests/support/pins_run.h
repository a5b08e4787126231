// Runs a list of operations through the pin-level device with PinHarness (the
// protocol a user's SoC follows) and returns what the pins gave. Elaborates a design
// and calls sc_start: once per test process.
#pragma once

#include "functional_coverage.h"

#include <vector>

#include "specular/pin_harness.h"

namespace specular {
namespace testing_support {

struct PinRun {
  std::vector<Result> results;
  std::vector<double> cycles;  ///< start → 35↑ per operation, in clock periods
};

class PinDriver : public sc_core::sc_module {
 public:
  PinDriver(sc_core::sc_module_name name, PinHarness& harness, const std::vector<Operands>& ops)
      : sc_module(name), harness_(harness), ops_(ops) {
    SPECULAR_HAS_PROCESS(PinDriver);
    SC_THREAD(run);
  }
  PinRun out;

 private:
  void run() {
    harness_.reset();
    harness_.run_batch(ops_, out.results);
    out.cycles = harness_.cycles();
    sc_core::sc_stop();
  }
  PinHarness& harness_;
  const std::vector<Operands>& ops_;
};

inline PinRun run_on_pins(const Config& config, const sc_core::sc_time& period,
                          const std::vector<Operands>& ops) {
  coverage::record_policy(config);  // functional coverage (issue 37): off unless asked
  for (const Operands& op : ops) coverage::record_operation(op, config.widths.cos_frac_bits);
  PinHarness harness("harness", config, period);
  PinDriver driver("driver", harness, ops);
  sc_core::sc_start();
  return driver.out;
}

}  // namespace testing_support
}  // namespace specular
