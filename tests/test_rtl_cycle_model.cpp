// The RTL twins as plain C++ on samples, quickly — RtlCycleModel (the drawn device) and
// RtlSyncCycleModel (the synchronous variant): every field of every result equals a Core
// built with the same widths, under every policy, with n, R, G, B reloaded between
// operations (3 T) or streaming (2 T), and 35 rises when each timing table says: 2.5
// periods after the start (the spec's table), 2 after the start edge (the variant's,
// docs/rtl.md), clock edges counted per operation alone, per streamed batch and per
// reload. The drawn twin also at the second width set it was verilated at (ROM 5 word
// 20 bits, register 9 S14.16: the RTL's parameters follow Formats). Other widths are
// refused with a message that names what is allowed; after a reset the next operation
// is correct (resets in the middle of an operation: the Icarus testbench). The
// exhaustive runs are test_long_rtl_exhaustive.cpp.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/twin/rtl_cycle_model.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#include "support/policies.h"

namespace specular {
namespace {

/// Start (edge) to 35↑ in clock periods: the spec's timing table, and docs/rtl.md's
/// table for the synchronous variant.
constexpr double drawn_periods = 2.5;
constexpr double sync_periods = 2.0;

/// `count` operations with cos codes, n and R, G, B drawn at random; with `stream`,
/// n, R, G, B are held for runs of 64 (2 T apart), else redrawn (3 T apart).
std::vector<Operands> random_operations(const Formats& f, std::size_t count, bool stream,
                                        std::uint64_t seed) {
  std::mt19937_64 engine(seed);
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

/// 20 000 random operations through `Model` under `config`, each against the core and
/// each 35↑ `periods` after its start. The devices the core refuses (a ROM 38 word it
/// cannot hold) the model refuses too, and there is nothing to compare.
template <class Model>
void expect_equal_to_core(const Config& config, bool stream, double periods, std::uint64_t seed) {
  try {
    const Core probe(config);
  } catch (const std::invalid_argument&) {
    EXPECT_THROW(Model rtl(config), std::invalid_argument);
    return;
  }
  const Core core(config);
  Model rtl(config);
  rtl.reset();
  const std::vector<Operands> ops = random_operations(core.formats(), 20000, stream, seed);
  std::vector<Result> out;
  rtl.run_batch(ops, out);
  ASSERT_EQ(out.size(), ops.size());
  std::size_t mismatches = 0, off_timing = 0;
  for (std::size_t i = 0; i < ops.size(); ++i) {
    const Result c = core.run(ops[i]);
    const Result& r = out[i];
    const bool same = r.reg1 == c.reg1 && r.reg9_pass1 == c.reg9_pass1 &&
                      r.reg9_pass2 == c.reg9_pass2 && r.rom38_k == c.rom38_k &&
                      r.norm39 == c.norm39 && r.out == c.out;
    if (!same && mismatches++ < 3)
      ADD_FAILURE() << "n " << ops[i].n << ", cos code " << ops[i].cos << ": reg9 " << r.reg9_pass2
                    << " vs " << c.reg9_pass2 << ", out " << r.out[0] << " vs " << c.out[0];
    if (rtl.cycles()[i] != periods && off_timing++ < 3)
      ADD_FAILURE() << "operation " << i << ": 35 rose " << rtl.cycles()[i] << " periods after start";
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(off_timing, 0u);
}

// ---- the drawn device (RtlCycleModel) ----------------------------------------------

class RtlCycleModelPolicies : public testing_support::DevicePolicyTest {
 protected:
  Config config(const Widths& widths) const {
    Config c = DevicePolicyTest::config();
    c.widths = widths;
    return c;
  }
  void expect_equal(const Widths& widths, bool stream) const {
    expect_equal_to_core<RtlCycleModel>(config(widths), stream, drawn_periods, 20261125);
  }
};

TEST_P(RtlCycleModelPolicies, DefaultWidthsReloadingEqualsTheCore) { expect_equal(Widths{}, false); }
TEST_P(RtlCycleModelPolicies, DefaultWidthsStreamingEqualsTheCore) { expect_equal(Widths{}, true); }
TEST_P(RtlCycleModelPolicies, AlternateWidthsEqualTheCoreAtTheSameWidths) {
  expect_equal(rtl_alternate_widths(), false);
}

INSTANTIATE_TEST_SUITE_P(Devices, RtlCycleModelPolicies, testing_support::every_device(),
                         testing_support::device_name);

TEST(RtlCycleModel, AlternateWidthsAreWhatTheDocsSay) {
  const Widths w = rtl_alternate_widths();
  EXPECT_EQ(w.rom5_word_bits, 20);
  EXPECT_EQ(w.reg9_frac_bits, 16);
  EXPECT_EQ(Formats(w).reg9.name(), "S14.16");
}

TEST(RtlCycleModel, OtherWidthsAreRefusedByName) {
  Config config;
  config.widths.rom5_addr_bits = 12;
  try {
    RtlCycleModel rtl(config);
    FAIL() << "widths the RTL was not verilated at were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rtl_alternate_widths"), std::string::npos) << e.what();
  }
}

TEST(RtlCycleModel, CountsHalfPeriods) {
  // One operation alone: 2.5 periods from start to 35↑ = 5 half periods, plus the
  // reset's period (2 half periods).
  RtlCycleModel rtl;
  rtl.reset();
  EXPECT_EQ(rtl.half_periods(), 2u);
  rtl.run({Formats().cos.one(), 1, {255, 255, 255}});
  EXPECT_EQ(rtl.half_periods(), 2u + 6u);  // start edge .. 35↑ at the 6th edge (5 half periods after start)
  EXPECT_EQ(rtl.cycles().at(0), drawn_periods);
}


// ---- the synchronous variant (RtlSyncCycleModel) ------------------------------------

class RtlSyncCycleModelPolicies : public testing_support::DevicePolicyTest {
 protected:
  void expect_equal(bool stream) const {
    expect_equal_to_core<RtlSyncCycleModel>(config(), stream, sync_periods, 20261202);
  }
};

TEST_P(RtlSyncCycleModelPolicies, ReloadingEqualsTheCore) { expect_equal(false); }
TEST_P(RtlSyncCycleModelPolicies, StreamingEqualsTheCore) { expect_equal(true); }

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
  EXPECT_EQ(rtl.cycles().at(0), sync_periods);
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
  EXPECT_EQ(rtl.cycles().at(0), sync_periods);
}

}  // namespace
}  // namespace specular
