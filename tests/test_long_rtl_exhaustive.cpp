// The RTL twins as plain C++ — RtlCycleModel (the drawn device, issue 13 must-have 5)
// and RtlSyncCycleModel (the synchronous variant, issue 19 must-have 2): the verilated
// device, no SystemC kernel — against the bit-accurate core on every cos code of
// register 1 × every n in 1..1000, under every normalisation × saturation × constants
// policy (the devices the core refuses, the twins refuse too): every field of every
// result — register 1, register 9 after each pass, ROM 38, multiplier 39, pins 24–26 —
// equal, and 35 rising when each timing table says: 2.5 clock periods after the start
// for the drawn device (the spec's table), 2 after the start edge for the variant
// (docs/rtl.md). The operations stream as the protocol allows (a start every 2 T while
// n, R, G, B stay); R, G, B change with n (a reload), so multipliers 13–15 see every
// intensity.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/twin/rtl_cycle_model.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#include "support/operation_shard.h"
#include "support/policies.h"

namespace specular {
namespace {

/// Start (edge) to 35↑ in clock periods: the spec's timing table, and docs/rtl.md's
/// table for the synchronous variant.
constexpr double drawn_periods = 2.5;
constexpr double sync_periods = 2.0;

/// Fields that differ, for a readable failure message ("" when none does).
std::string differing_fields(const Result& rtl, const Result& core) {
  std::string fields;
  if (rtl.reg1 != core.reg1) fields += " reg1";
  if (rtl.reg9_pass1 != core.reg9_pass1) fields += " reg9_pass1";
  if (rtl.reg9_pass2 != core.reg9_pass2) fields += " reg9_pass2";
  if (rtl.rom38_k != core.rom38_k) fields += " rom38_k";
  if (rtl.norm39 != core.norm39) fields += " norm39";
  if (rtl.out != core.out) fields += " out";
  return fields;
}

/// False for the devices the core refuses to build (Rom38Table's check).
bool buildable(const Config& config) {
  try {
    const Core core(config);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

/// Every cos code × every n through `Model` (RtlCycleModel or RtlSyncCycleModel) under
/// `config`, each result against the core's and each 35↑ `periods` after its start.
template <class Model>
void expect_every_operation_equals_the_core(const Config& config, double periods) {
  if (!buildable(config)) {
    // The core refuses this device (a ROM 38 word it cannot hold): so must the twin.
    EXPECT_THROW(Model rtl(config), std::invalid_argument);
    return;
  }
  const Core core(config);
  const code_t cos_codes = core.formats().cos.one() + 1;  // 0 .. 1.0
  Model rtl(config);
  rtl.reset();

  std::vector<Operands> batch(static_cast<std::size_t>(cos_codes));
  std::vector<Result> out;
  std::size_t operations = 0, mismatches = 0, off_timing = 0;
  std::string first_mismatch;
  const testing_support::OperationShard shard = testing_support::operation_shard();
  const auto started = std::chrono::steady_clock::now();
  for (code_t n = n_min; n <= static_cast<code_t>(n_max); ++n) {
    if (!shard.covers(static_cast<unsigned>(n))) continue;
    // R, G, B walk through 0..255 with n (three different steps).
    const std::array<code_t, 3> rgb = {(n * 1) % 256, (n * 7 + 3) % 256, (n * 101 + 250) % 256};
    for (code_t c = 0; c < cos_codes; ++c) batch[static_cast<std::size_t>(c)] = {c, n, rgb};
    rtl.run_batch(batch, out);
    for (std::size_t i = 0; i < batch.size(); ++i) {
      const std::string fields = differing_fields(out[i], core.run(batch[i]));
      if (!fields.empty() && mismatches++ == 0)
        first_mismatch = "n " + std::to_string(n) + ", cos code " + std::to_string(batch[i].cos) + ":" + fields;
      if (rtl.cycles()[i] != periods) ++off_timing;
    }
    operations += batch.size();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cout << "policy " << to_string(config.normalisation) << "/" << to_string(config.saturation)
            << "/" << to_string(config.constants) << ", shard " << shard.text() << " of n: "
            << operations << " operations, "
            << mismatches << " differences, " << seconds << " s (" << operations / seconds / 1e6
            << " M results/s including the core and the comparison)\n";

  EXPECT_EQ(operations, static_cast<std::size_t>(cos_codes) * shard.covered(n_min, n_max));
  EXPECT_EQ(mismatches, 0u) << "first at " << first_mismatch;
  EXPECT_EQ(off_timing, 0u) << "operations whose 35 did not rise " << periods << " periods after start";
}

class RtlExhaustive : public testing_support::DevicePolicyTest {};
TEST_P(RtlExhaustive, EveryCosCodeAndEveryNEqualsTheCore) {
  expect_every_operation_equals_the_core<RtlCycleModel>(config(), drawn_periods);
}
INSTANTIATE_TEST_SUITE_P(Devices, RtlExhaustive, testing_support::every_device(),
                         testing_support::device_name);

class RtlSyncExhaustive : public testing_support::DevicePolicyTest {};
TEST_P(RtlSyncExhaustive, EveryCosCodeAndEveryNEqualsTheCore) {
  expect_every_operation_equals_the_core<RtlSyncCycleModel>(config(), sync_periods);
}
INSTANTIATE_TEST_SUITE_P(Devices, RtlSyncExhaustive, testing_support::every_device(),
                         testing_support::device_name);

}  // namespace
}  // namespace specular
