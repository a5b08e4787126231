// The specialised verilations of the synchronous variant and the drawn twin (issue 28; docs/rtl/sync.md,
// "Specialised verilation"), quickly: which runs use it (the plain C++ model, the TLM
// rtl-sync target and specular_tb --model rtl-sync whenever the Config matches a
// specialised build; the general model otherwise and for a VCD), and its results
// against the core on random operations, reloading and streaming, in C++ and under the
// SystemC harness. Every cos code × every n: tests/test_long_rtl_fixed.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "run_models.h"
#include "specular/core.h"
#include "specular/twin/rtl_cycle_model.h"
#include "specular/twin/rtl_device.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#include "specular/twin/rtl_sync_device.h"

namespace specular {
namespace {

bool same_result(const Result& a, const Result& b) {
  return a.reg1 == b.reg1 && a.reg9_pass1 == b.reg9_pass1 && a.reg9_pass2 == b.reg9_pass2 &&
         a.rom38_k == b.rom38_k && a.norm39 == b.norm39 && a.out == b.out;
}

bool built(const Config& config) {
  const std::vector<Config> configs = rtl_sync_fixed_configs();
  return std::any_of(configs.begin(), configs.end(), [&](const Config& c) {
    return c.constants == config.constants && c.normalisation == config.normalisation &&
           c.saturation == config.saturation;
  });
}

/// 20 000 operations, cos λ random; n, R, G, B new every operation or held in runs of 64.
std::vector<Operands> random_operations(const Formats& f, bool stream, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Operands> ops(20000);
  Operands held{};
  for (std::size_t i = 0; i < ops.size(); ++i) {
    if (!stream || i % 64 == 0)
      held = {0, static_cast<code_t>(1 + rng() % 1000),
              {static_cast<code_t>(rng() % 256), static_cast<code_t>(rng() % 256),
               static_cast<code_t>(rng() % 256)}};
    ops[i] = held;
    ops[i].cos = static_cast<code_t>(rng() % static_cast<std::uint64_t>(f.cos.one() + 1));
  }
  return ops;
}

TEST(RtlSyncFixed, TheDefaultDeviceIsBuiltAndChosenWhereverItsConfigRuns) {
  EXPECT_TRUE(built(Config{}));
  EXPECT_TRUE(RtlSyncCycleModel().fixed());
  EXPECT_FALSE(RtlSyncCycleModel(Config{}, /*allow_fixed=*/false).fixed());
  Config other;
  other.constants = Constants::minimax;
  other.normalisation = Normalisation::energy;
  other.saturation = Saturation::literal;
  EXPECT_EQ(RtlSyncCycleModel(other).fixed(), built(other));
}

TEST(RtlSyncFixed, ReloadingAndStreamingEqualTheCoreAndTheGeneralModel) {
  const Core core;
  for (const bool stream : {false, true}) {
    const std::vector<Operands> ops = random_operations(core.formats(), stream, 28);
    RtlSyncCycleModel fixed, general(Config{}, false);
    ASSERT_TRUE(fixed.fixed());
    fixed.reset();
    general.reset();
    std::vector<Result> a, b;
    fixed.run_batch(ops, a);
    general.run_batch(ops, b);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < ops.size(); ++i) {
      const Result c = core.run(ops[i]);
      if ((!same_result(a[i], c) || !same_result(b[i], c) || fixed.cycles()[i] != 2.0) &&
          mismatches++ < 3)
        ADD_FAILURE() << (stream ? "streaming" : "reloading") << ", operation " << i << ": n "
                      << ops[i].n << ", cos code " << ops[i].cos << ": pin 24 " << a[i].out[0]
                      << " (general " << b[i].out[0] << ", core " << c.out[0] << ")";
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(fixed.half_periods(), general.half_periods()) << "the same clock edges";
  }
}

TEST(RtlSyncFixed, TheHarnessRunsItAndTheGeneralTracedModelForAVcd) {
  RtlSyncHarness harness("harness", Config{}, sc_core::sc_time(10, sc_core::SC_NS));
  EXPECT_TRUE(harness.dut.fixed());
  harness.dut.open_vcd(testing::TempDir() + "rtl_sync_fixed.vcd");
  EXPECT_FALSE(harness.dut.fixed()) << "the specialised model has no trace code";
}

// specular_tb --model rtl-sync's run (the harness makes RtlSyncDevice with the run's
// Config, the default here: the specialised model, evaluated at rising edges only):
// reloading operations, then streaming ones, in one elaboration.
TEST(RtlSyncFixed, SpecularTbModelRtlSyncEqualsTheCoreOnIt) {
  tb::RunSettings settings;
  settings.model = tb::Model::rtl_sync;
  const Core core;
  std::vector<Operands> ops = random_operations(core.formats(), false, 2028);
  const std::vector<Operands> streamed = random_operations(core.formats(), true, 2029);
  ops.insert(ops.end(), streamed.begin(), streamed.end());
  std::vector<Result> results;
  std::vector<double> cycles;
  tb::run_operations(settings, ops, results, cycles);
  ASSERT_EQ(results.size(), ops.size());
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < ops.size(); ++i)
    if ((!same_result(results[i], core.run(ops[i])) || cycles[i] != 2.0) && mismatches++ < 3)
      ADD_FAILURE() << "operation " << i << ": n " << ops[i].n << ", cos code " << ops[i].cos
                    << ", " << cycles[i] << " periods";
  EXPECT_EQ(mismatches, 0u);
}

// The drawn twin: RtlCycleModel (and so the TLM rtl target) and RtlDevice.
TEST(RtlFixed, TheDrawnTwinIsBuiltAndChosenWhereverItsConfigRuns) {
  EXPECT_TRUE(RtlCycleModel().fixed());
  EXPECT_FALSE(RtlCycleModel(Config{}, /*allow_fixed=*/false).fixed());
  Config other;
  other.constants = Constants::minimax;
  other.normalisation = Normalisation::energy;
  other.saturation = Saturation::literal;
  EXPECT_EQ(RtlCycleModel(other).fixed(), built(other));
}

TEST(RtlFixed, DrawnReloadingAndStreamingEqualTheCoreAndTheGeneralModel) {
  const Core core;
  for (const bool stream : {false, true}) {
    const std::vector<Operands> ops = random_operations(core.formats(), stream, 2813);
    RtlCycleModel fixed, general(Config{}, false);
    ASSERT_TRUE(fixed.fixed());
    fixed.reset();
    general.reset();
    std::vector<Result> a, b;
    fixed.run_batch(ops, a);
    general.run_batch(ops, b);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < ops.size(); ++i) {
      const Result c = core.run(ops[i]);
      if ((!same_result(a[i], c) || !same_result(b[i], c) || fixed.cycles()[i] != 2.5) &&
          mismatches++ < 3)
        ADD_FAILURE() << (stream ? "streaming" : "reloading") << ", operation " << i;
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(fixed.half_periods(), general.half_periods());
  }
}

TEST(RtlFixed, TheDrawnHarnessRunsItAndTheGeneralTracedModelForAVcd) {
  RtlHarness harness("harness", Config{}, sc_core::sc_time(10, sc_core::SC_NS));
  EXPECT_TRUE(harness.dut.fixed());
  harness.dut.open_vcd(testing::TempDir() + "rtl_fixed.vcd");
  EXPECT_FALSE(harness.dut.fixed());
}

TEST(RtlFixed, SpecularTbModelRtlEqualsTheCoreOnIt) {
  tb::RunSettings settings;
  settings.model = tb::Model::rtl;
  const Core core;
  std::vector<Operands> ops = random_operations(core.formats(), false, 2030);
  const std::vector<Operands> streamed = random_operations(core.formats(), true, 2031);
  ops.insert(ops.end(), streamed.begin(), streamed.end());
  std::vector<Result> results;
  std::vector<double> cycles;
  tb::run_operations(settings, ops, results, cycles);
  ASSERT_EQ(results.size(), ops.size());
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < ops.size(); ++i)
    if ((!same_result(results[i], core.run(ops[i])) || cycles[i] != 2.5) && mismatches++ < 3)
      ADD_FAILURE() << "operation " << i << ": n " << ops[i].n << ", cos code " << ops[i].cos;
  EXPECT_EQ(mismatches, 0u);
}

}  // namespace
}  // namespace specular
