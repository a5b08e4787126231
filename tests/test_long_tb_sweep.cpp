// The --sweep grid (every n in 1..1000 × 1021 cos values) through the pins under
// every normalisation × saturation policy (issue 2 item 7: "pin model and core agree
// bit for bit", "sample the pin model"): every field of every result equals the
// core's, every result is within the bounds of the double reference, and every
// latency is 2.5 periods. The printed summary is the pin row of docs/accuracy.md.
// The same for the RTL twin under the same harness (`--model rtl`): equal to the core,
// and so to the pin model, bit for bit, at 2.5 periods per operation; and for the
// synchronous variant (`--model rtl-sync`) at its own 2 periods (docs/rtl.md).
#include <gtest/gtest.h>

#include <iostream>
#include <stdexcept>
#include <sstream>
#include <tuple>

#include "input.h"
#include "report.h"
#include "run_models.h"
#include "scoreboard.h"
#include "specular/core.h"
#include "support/policies.h"
#include "support/sharded_sweep.h"

namespace specular {
namespace tb {
namespace {

// Each test covers the operation shard's slice of n: under GoogleTest's sharding, every
// shard process runs it on its own slice (support/operation_shard.h).
SPECULAR_OPERATION_SHARDED_SUITE(PinSweep);
SPECULAR_OPERATION_SHARDED_SUITE(RtlSweep);
SPECULAR_OPERATION_SHARDED_SUITE(RtlSyncSweep);

/// Runs the sweep on `model` under the test's policy and checks every result; every
/// operation must take `expected_cycles` from start to 35↑ (the model's timing table).
void sweep_against_core(Model model, const Config& config, double expected_cycles = 2.5) {
  RunSettings settings;
  settings.model = model;
  settings.config = config;
  const Core core(settings.config);
  const Formats& f = core.formats();
  SweepSource sweep(f, {255, 128, 1});
  Scoreboard scoreboard(settings.config, expected_cycles);
  std::vector<Stimulus> stimuli;
  std::size_t mismatches = 0;
  std::string first_mismatch;

  const testing_support::OperationShard shard = testing_support::operation_shard();
  const OperandSource source = testing_support::sharded_sweep(sweep, stimuli, shard);
  const ResultSink sink = [&](const std::vector<Operands>& chunk, const std::vector<Result>& results,
                              const std::vector<double>& cycles) {
    for (std::size_t i = 0; i < results.size(); ++i) {
      const Result c = core.run(chunk[i]);
      const Result& p = results[i];
      const bool same = p.reg1 == c.reg1 && p.reg9_pass1 == c.reg9_pass1 &&
                        p.reg9_pass2 == c.reg9_pass2 && p.rom38_k == c.rom38_k &&
                        p.norm39 == c.norm39 && p.out == c.out;
      if (!same && mismatches++ == 0)
        first_mismatch = "n " + std::to_string(chunk[i].n) + ", cos code " + std::to_string(chunk[i].cos);
      scoreboard.record(scoreboard.compare(stimuli[i], p, cycles[i]));
    }
  };
  run_operations(settings, source, sink);

  const Summary& s = scoreboard.summary();
  std::ostringstream text;
  RunDescription run;
  run.model = to_string(model);
  run.config = settings.config;
  write_summary_text(text, s, run, -1);
  std::cout << "model=" << to_string(model) << " constants=" << to_string(settings.config.constants) << " policy=" << to_string(settings.config.normalisation)
            << " saturation=" << to_string(settings.config.saturation) << '\n'
            << text.str() << std::flush;
  ::testing::Test::RecordProperty("summary", text.str());

  EXPECT_EQ(s.count, 1021u * shard.covered(n_min, n_max));
  EXPECT_EQ(mismatches, 0u) << "first at " << first_mismatch;
  EXPECT_EQ(s.failures, 0u) << text.str();
  EXPECT_EQ(s.cycles_min, expected_cycles);
  EXPECT_EQ(s.cycles_max, expected_cycles);
}

class PinSweep : public testing_support::PolicyTest {};
class RtlSweep : public testing_support::DevicePolicyTest {};

TEST_P(PinSweep, PinEqualsCoreBitForBitAndMeetsTheBounds) {
  Config config;
  config.normalisation = std::get<0>(GetParam());
  config.saturation = std::get<1>(GetParam());
  sweep_against_core(Model::pin, config);
}
// The twin under every constants policy too; the devices the core refuses, it refuses.
TEST_P(RtlSweep, RtlEqualsCoreBitForBitAndMeetsTheBounds) {
  try {
    const Core core(config());
  } catch (const std::invalid_argument&) {
    const Config refused = config();
    EXPECT_THROW(sweep_against_core(Model::rtl, refused), std::invalid_argument);
    return;
  }
  sweep_against_core(Model::rtl, config());
}

// The synchronous variant under the same harness with its protocol: 2 periods each.
class RtlSyncSweep : public testing_support::DevicePolicyTest {};
TEST_P(RtlSyncSweep, RtlSyncEqualsCoreBitForBitAndMeetsTheBounds) {
  try {
    const Core core(config());
  } catch (const std::invalid_argument&) {
    const Config refused = config();
    EXPECT_THROW(sweep_against_core(Model::rtl_sync, refused, 2.0), std::invalid_argument);
    return;
  }
  sweep_against_core(Model::rtl_sync, config(), 2.0);
}

INSTANTIATE_TEST_SUITE_P(Policies, PinSweep, testing_support::every_policy(),
                         testing_support::policy_name);
INSTANTIATE_TEST_SUITE_P(Devices, RtlSweep, testing_support::every_device(),
                         testing_support::device_name);
INSTANTIATE_TEST_SUITE_P(Devices, RtlSyncSweep, testing_support::every_device(),
                         testing_support::device_name);

}  // namespace
}  // namespace tb
}  // namespace specular
