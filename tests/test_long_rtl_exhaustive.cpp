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

#include <memory>

#include "specular/core.h"
#include "specular/twin/rtl_cycle_model.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#include "support/policies.h"
#include "support/rtl_exhaustive.h"

namespace specular {
namespace {

// Each test covers the operation shard's slice of n: under GoogleTest's sharding, every
// shard process runs it on its own slice (support/operation_shard.h).
SPECULAR_OPERATION_SHARDED_SUITE(RtlExhaustive);
SPECULAR_OPERATION_SHARDED_SUITE(RtlSyncExhaustive);
using testing_support::drawn_periods;
using testing_support::expect_every_operation_equals_the_core;
using testing_support::sync_periods;

class RtlExhaustive : public testing_support::DevicePolicyTest {};
// The general verilation on every device (specialised ones: tests/test_long_rtl_fixed.cpp).
TEST_P(RtlExhaustive, EveryCosCodeAndEveryNEqualsTheCore) {
  expect_every_operation_equals_the_core<RtlCycleModel>(
      config(), drawn_periods,
      [](const Config& c) { return std::make_unique<RtlCycleModel>(c, /*allow_fixed=*/false); });
}
INSTANTIATE_TEST_SUITE_P(Devices, RtlExhaustive, testing_support::every_device(),
                         testing_support::device_name);

class RtlSyncExhaustive : public testing_support::DevicePolicyTest {};
// The general verilation on every device, the default one included (its specialised
// verilation: tests/test_long_rtl_fixed.cpp).
TEST_P(RtlSyncExhaustive, EveryCosCodeAndEveryNEqualsTheCore) {
  expect_every_operation_equals_the_core<RtlSyncCycleModel>(
      config(), sync_periods,
      [](const Config& c) { return std::make_unique<RtlSyncCycleModel>(c, /*allow_fixed=*/false); });
}
INSTANTIATE_TEST_SUITE_P(Devices, RtlSyncExhaustive, testing_support::every_device(),
                         testing_support::device_name);

}  // namespace
}  // namespace specular
