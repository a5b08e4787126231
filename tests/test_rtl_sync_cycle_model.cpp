// The synchronous variant as plain C++ (RtlSyncCycleModel) on samples, quickly: every
// field of every result equals the core under every policy, with n, R, G, B reloaded
// between operations (3 T) or streaming (2 T); the variant's timing table (docs/rtl.md):
// 35↑ 2 periods after each start edge, clock edges per operation alone, per streamed
// batch and per reload; other widths refused by name; after a reset the next operation
// is correct (resets in the middle of an operation: the Icarus testbench). The
// exhaustive run is test_long_rtl_sync_exhaustive.cpp.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#include "support/policies.h"

namespace specular {
namespace {

/// `count` operations with cos codes, n and R, G, B drawn at random; with `stream`,
/// n, R, G, B are held for runs of 64 (2 T apart), else redrawn (3 T apart).
std::vector<Operands> random_operations(const Formats& f, std::size_t count, bool stream) {
  std::mt19937_64 engine(20261202);
  std::vector<Operands> ops(count);
  Operands held;
  for (std::size_t i = 0; i < count; ++i) {
    if (!stream || i % 64 == 0) {
      held.n = static_cast<code_t>(engine() % n_max) + 1;
      for (code_t& c : held.rgb) c = static_cast<code_t>(engine() % (f.rgb.max_code() + 1));
    }
    ops[i] = held;
    ops[i].cos = static_cast<code_t>(engine() % static_cast<std::uint64_t>(f.cos.one() + 1));
  }
  return ops;
}

std::size_t mismatches_against_core(const Core& core, const std::vector<Operands>& ops,
                                    const std::vector<Result>& out) {
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < ops.size(); ++i) {
    const Result c = core.run(ops[i]);
    const Result& r = out[i];
    const bool same = r.reg1 == c.reg1 && r.reg9_pass1 == c.reg9_pass1 &&
                      r.reg9_pass2 == c.reg9_pass2 && r.rom38_k == c.rom38_k &&
                      r.norm39 == c.norm39 && r.out == c.out;
    if (!same && mismatches++ < 3)
      ADD_FAILURE() << "n " << ops[i].n << ", cos code " << ops[i].cos << ": reg9 " << r.reg9_pass2
                    << " vs " << c.reg9_pass2 << ", out " << r.out[0] << " vs " << c.out[0];
  }
  return mismatches;
}

class RtlSyncCycleModelPolicies : public testing_support::DevicePolicyTest {
 protected:
  void expect_equal_to_core(bool stream) {
    const Config c = config();
    try {
      const Core probe(c);
    } catch (const std::invalid_argument&) {
      EXPECT_THROW(RtlSyncCycleModel rtl(c), std::invalid_argument);
      return;
    }
    const Core core(c);
    RtlSyncCycleModel rtl(c);
    rtl.reset();
    const std::vector<Operands> ops = random_operations(core.formats(), 20000, stream);
    std::vector<Result> out;
    rtl.run_batch(ops, out);
    ASSERT_EQ(out.size(), ops.size());
    EXPECT_EQ(mismatches_against_core(core, ops, out), 0u);
    for (std::size_t i = 0; i < ops.size(); ++i)
      ASSERT_EQ(rtl.cycles()[i], 2.0) << "operation " << i;
  }
};

TEST_P(RtlSyncCycleModelPolicies, ReloadingEqualsTheCore) { expect_equal_to_core(false); }
TEST_P(RtlSyncCycleModelPolicies, StreamingEqualsTheCore) { expect_equal_to_core(true); }

INSTANTIATE_TEST_SUITE_P(Devices, RtlSyncCycleModelPolicies, testing_support::every_device(),
                         testing_support::device_name);

TEST(RtlSyncCycleModel, OtherWidthsAreRefusedByName) {
  Config config;
  config.widths.rom5_addr_bits = 12;
  try {
    RtlSyncCycleModel rtl(config);
    FAIL() << "widths the synchronous RTL was not verilated at were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("default widths"), std::string::npos) << e.what();
  }
}

TEST(RtlSyncCycleModel, CountsClockEdgesAsTheTimingTableSays) {
  // Reset: one period (2 edges). One operation alone: 35↑ on the 5th edge from its
  // start edge (2 T after it), then the falling edge: 6 edges. A batch of k streamed
  // (2 T apart): 4k + 2. A reload between two operations: one period (2 edges) more.
  RtlSyncCycleModel rtl;
  rtl.reset();
  EXPECT_EQ(rtl.half_periods(), 2u);
  rtl.run({Formats().cos.one(), 1, {255, 255, 255}});
  EXPECT_EQ(rtl.half_periods(), 2u + 6u);
  EXPECT_EQ(rtl.cycles().at(0), 2.0);
  std::vector<Operands> ops(10, Operands{0, 1, {255, 255, 255}});
  for (std::size_t i = 0; i < ops.size(); ++i) ops[i].cos = static_cast<code_t>(i * 1000);
  std::vector<Result> out;
  rtl.run_batch(ops, out);
  EXPECT_EQ(rtl.half_periods(), 2u + 6u + 42u);
  for (std::size_t i = 5; i < ops.size(); ++i) ops[i].n = 2;  // one reload, before ops[5]
  rtl.run_batch(ops, out);
  EXPECT_EQ(rtl.half_periods(), 2u + 6u + 42u + 44u);
}

TEST(RtlSyncCycleModel, ResetReturnsToIdleAndTheNextOperationIsCorrect) {
  const Core core{Config{}};
  RtlSyncCycleModel rtl;
  rtl.reset();
  const Operands first{12345, 17, {1, 2, 3}}, second{54321, 999, {250, 128, 7}};
  EXPECT_EQ(rtl.run(first).out, core.run(first).out);
  rtl.reset();
  const Result r = rtl.run(second);
  EXPECT_EQ(r.reg9_pass2, core.run(second).reg9_pass2);
  EXPECT_EQ(r.out, core.run(second).out);
  EXPECT_EQ(rtl.cycles().at(0), 2.0);
}

}  // namespace
}  // namespace specular
