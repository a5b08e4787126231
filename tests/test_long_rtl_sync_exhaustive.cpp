// The synchronous variant (rtl/specular_device_sync.v) as plain C++ (RtlSyncCycleModel)
// against the bit-accurate core on every cos code of register 1 × every n in 1..1000,
// under every normalisation × saturation × constants policy (issue 19, must-have 2; the
// devices the core refuses, the variant refuses too): every field of every result —
// register 1, register 9 after each pass, ROM 38, multiplier 39, pins 24–26 — equal,
// and 2 clock periods from each start edge to 35↑ (the variant's timing table,
// docs/rtl.md). The operations stream at 2 T; R, G, B change with n (a reload at 3 T),
// so multipliers 13–15 see every intensity.
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#include "support/policies.h"

namespace specular {
namespace {

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

class RtlSyncExhaustive : public testing_support::DevicePolicyTest {};

TEST_P(RtlSyncExhaustive, EveryCosCodeAndEveryNEqualsTheCore) {
  const Config config = this->config();
  if (!buildable(config)) {
    EXPECT_THROW(RtlSyncCycleModel rtl(config), std::invalid_argument);
    return;
  }
  const Core core(config);
  const code_t cos_codes = core.formats().cos.one() + 1;  // 0 .. 1.0
  RtlSyncCycleModel rtl(config);
  rtl.reset();

  std::vector<Operands> batch(static_cast<std::size_t>(cos_codes));
  std::vector<Result> out;
  std::size_t operations = 0, mismatches = 0, off_timing = 0;
  std::string first_mismatch;
  const auto started = std::chrono::steady_clock::now();
  for (code_t n = n_min; n <= static_cast<code_t>(n_max); ++n) {
    const std::array<code_t, 3> rgb = {(n * 1) % 256, (n * 7 + 3) % 256, (n * 101 + 250) % 256};
    for (code_t c = 0; c < cos_codes; ++c) batch[static_cast<std::size_t>(c)] = {c, n, rgb};
    rtl.run_batch(batch, out);
    for (std::size_t i = 0; i < batch.size(); ++i) {
      const std::string fields = differing_fields(out[i], core.run(batch[i]));
      if (!fields.empty() && mismatches++ == 0)
        first_mismatch = "n " + std::to_string(n) + ", cos code " + std::to_string(batch[i].cos) + ":" + fields;
      if (rtl.cycles()[i] != 2.0) ++off_timing;
    }
    operations += batch.size();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cout << "policy " << to_string(config.normalisation) << "/" << to_string(config.saturation)
            << "/" << to_string(config.constants) << ": " << operations << " operations, "
            << mismatches << " differences, " << seconds << " s (" << operations / seconds / 1e6
            << " M results/s including the core and the comparison)\n";

  EXPECT_EQ(operations, static_cast<std::size_t>(cos_codes) * n_max);
  EXPECT_EQ(mismatches, 0u) << "first at " << first_mismatch;
  EXPECT_EQ(off_timing, 0u) << "operations whose 35 did not rise 2 periods after start";
}

INSTANTIATE_TEST_SUITE_P(Devices, RtlSyncExhaustive, testing_support::every_device(),
                         testing_support::device_name);

}  // namespace
}  // namespace specular
