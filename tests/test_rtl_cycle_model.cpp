// The RTL twin as plain C++ (RtlCycleModel) on samples, quickly: at the default widths
// and at the second width set it was verilated at (ROM 5 word 20 bits, register 9
// S14.16: the RTL's parameters follow Formats), every field of every result equals a
// Core built with the same widths, under every policy, with n, R, G, B reloaded
// between operations (3 T) or streaming (2 T), at 2.5 periods each. Other widths are
// refused with a message that names the two sets. The exhaustive run is
// test_long_rtl_exhaustive.cpp.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/twin/rtl_cycle_model.h"
#include "support/policies.h"

namespace specular {
namespace {

/// `count` operations with cos codes, n and R, G, B drawn at random; with `stream`,
/// n, R, G, B are held for runs of 64 (the pipelined 2 T protocol), else redrawn.
std::vector<Operands> random_operations(const Formats& f, std::size_t count, bool stream) {
  std::mt19937_64 engine(20261125);
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

void expect_equal_to_core(const Config& config, bool stream) {
  const Core core(config);
  RtlCycleModel rtl(config);
  rtl.reset();
  const std::vector<Operands> ops = random_operations(core.formats(), 20000, stream);
  std::vector<Result> out;
  rtl.run_batch(ops, out);
  ASSERT_EQ(out.size(), ops.size());
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
    EXPECT_EQ(rtl.cycles()[i], 2.5) << "operation " << i;
  }
  EXPECT_EQ(mismatches, 0u);
}

class RtlCycleModelPolicies : public testing_support::DevicePolicyTest {
 protected:
  Config config(const Widths& widths) const {
    Config c = DevicePolicyTest::config();
    c.widths = widths;
    return c;
  }
  /// The devices the core refuses (a ROM 38 word it cannot hold): the twin refuses them
  /// too, and there is nothing to compare.
  bool refused(const Config& c) const {
    try {
      const Core core(c);
      return false;
    } catch (const std::invalid_argument&) {
      EXPECT_THROW(RtlCycleModel rtl(c), std::invalid_argument);
      return true;
    }
  }
};

TEST_P(RtlCycleModelPolicies, DefaultWidthsReloadingEqualsTheCore) {
  if (!refused(config(Widths{}))) expect_equal_to_core(config(Widths{}), false);
}
TEST_P(RtlCycleModelPolicies, DefaultWidthsStreamingEqualsTheCore) {
  if (!refused(config(Widths{}))) expect_equal_to_core(config(Widths{}), true);
}
TEST_P(RtlCycleModelPolicies, AlternateWidthsEqualTheCoreAtTheSameWidths) {
  if (!refused(config(rtl_alternate_widths()))) expect_equal_to_core(config(rtl_alternate_widths()), false);
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
  EXPECT_EQ(rtl.cycles().at(0), 2.5);
}

}  // namespace
}  // namespace specular
