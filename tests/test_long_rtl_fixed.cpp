// The specialised verilations of the synchronous variant and of the drawn twin (issue 28;
// docs/rtl/sync.md, "Specialised verilation"): for every configuration this build verilated them for
// (rtl_sync_fixed_configs(): the default device, and those -DSPECULAR_RTL_SYNC_FIXED
// adds), every cos code × every n in 1..1000 through RtlSyncCycleModel on that model
// against the core — every field of every result, and 35 rising 2 periods after each
// start edge (2.5 for the drawn twin). The synchronous model skips Verilator's falling-edge eval() (twin/src/verilated_clock.h)
// and holds ROM 38 as a read-only public memory (twin/fixed/rom_words_fixed.vlt): this is
// the proof that neither changes a bit.
#include <gtest/gtest.h>

#include <memory>

#include "specular/core.h"
#include "specular/twin/rtl_cycle_model.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#include "support/rtl_exhaustive.h"

namespace specular {
namespace {

// Each test covers the operation shard's slice of n: under GoogleTest's sharding, every
// shard process runs it on its own slice (support/operation_shard.h).
SPECULAR_OPERATION_SHARDED_SUITE(RtlSyncFixedExhaustive);
SPECULAR_OPERATION_SHARDED_SUITE(RtlFixedExhaustive);

TEST(RtlSyncFixedExhaustive, EveryBuiltConfigurationEqualsTheCoreOnEveryCosCodeAndEveryN) {
  const std::vector<Config> configs = rtl_sync_fixed_configs();
  ASSERT_FALSE(configs.empty()) << "the default device's specialised model is always built";
  for (const Config& config : configs) {
    SCOPED_TRACE(std::string(to_string(config.constants)) + "/" +
                 to_string(config.normalisation) + "/" + to_string(config.saturation));
    testing_support::expect_every_operation_equals_the_core<RtlSyncCycleModel>(
        config, testing_support::sync_periods, [](const Config& c) {
          auto model = std::make_unique<RtlSyncCycleModel>(c);
          EXPECT_TRUE(model->fixed()) << "a built configuration runs on its specialised model";
          return model;
        });
  }
}

// The drawn twin (specular_device.v) verilated with the same parameters (RtlCycleModel):
// 2.5 periods from start to 35↑, the spec's timing table.
TEST(RtlFixedExhaustive, EveryBuiltConfigurationEqualsTheCoreOnEveryCosCodeAndEveryN) {
  const std::vector<Config> configs = rtl_sync_fixed_configs();
  ASSERT_FALSE(configs.empty());
  for (const Config& config : configs) {
    SCOPED_TRACE(std::string(to_string(config.constants)) + "/" +
                 to_string(config.normalisation) + "/" + to_string(config.saturation));
    testing_support::expect_every_operation_equals_the_core<RtlCycleModel>(
        config, testing_support::drawn_periods, [](const Config& c) {
          auto model = std::make_unique<RtlCycleModel>(c);
          EXPECT_TRUE(model->fixed()) << "a built configuration runs on its specialised model";
          return model;
        });
  }
}

}  // namespace
}  // namespace specular
