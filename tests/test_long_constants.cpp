// Issue 14 item 4, exhaustively: the core at the default widths against the double
// reference for every n in 1..1000 × every cos code under each constants policy (the
// README's accuracy rows), with the device's own approximation s·A (multiplier 39
// under normalisation none) within 0.042 of cos_q^n under minimax, 0.075 under
// minimax-half; and the --sweep grid through the pins and through the TLM target,
// bit for bit equal to the core, under each minimax policy.
#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <tuple>

#include "input.h"
#include "report.h"
#include "run_models.h"
#include "scoreboard.h"
#include "specular/core.h"
#include "support/accuracy_sweep.h"
#include "support/sharded_sweep.h"

namespace specular {
namespace {

// Each test covers the operation shard's slice of n: under GoogleTest's sharding, every
// shard process runs it on its own slice (support/operation_shard.h).
SPECULAR_OPERATION_SHARDED_SUITE(ExhaustiveConstants);
SPECULAR_OPERATION_SHARDED_SUITE(ModelSweep);

using Combination = std::tuple<Constants, Normalisation, Saturation>;

std::string combination_name(const ::testing::TestParamInfo<Combination>& info) {
  std::string name = std::string(to_string(std::get<0>(info.param))) + "_" +
                     to_string(std::get<1>(info.param)) + "_" + to_string(std::get<2>(info.param));
  for (char& ch : name)
    if (ch == '-') ch = '_';
  return name;
}

class ExhaustiveConstants : public ::testing::TestWithParam<Combination> {};

TEST_P(ExhaustiveConstants, EveryNAndEveryCosCodeMeetsTheBounds) {
  Config config;
  std::tie(config.constants, config.normalisation, config.saturation) = GetParam();
  const Formats formats(config.widths);
  const auto codes = testing_support::cos_codes(formats, 1);
  const testing_support::OperationShard shard = testing_support::operation_shard();
  const testing_support::SweepFigures s = testing_support::sweep(config, codes, shard);
  const std::string line = testing_support::summary(config, s);
  std::cout << (shard.whole() ? "" : "shard " + shard.text() + " of n: ") << line << std::endl;
  RecordProperty("accuracy", line);

  EXPECT_EQ(s.evaluations, static_cast<long>(shard.covered(n_min, n_max)) * (formats.cos.one() + 1));
  EXPECT_EQ(s.approx_misses, 0) << s.first_miss;
  EXPECT_EQ(s.norm_misses, 0) << s.first_miss;
  EXPECT_EQ(s.out_misses, 0) << s.first_miss;
  EXPECT_EQ(s.pass1_misses, 0) << s.first_miss;
  if (config.saturation == Saturation::clamp && config.normalisation == Normalisation::none) {
    const double bound = config.constants == Constants::minimax        ? 0.042
                         : config.constants == Constants::minimax_half ? 0.075
                                                                       : 0.125 + 1e-4;
    EXPECT_LE(s.lobe_exact.error, bound) << "at " << testing_support::where(formats, s.lobe_exact);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Minimax, ExhaustiveConstants,
    ::testing::Combine(::testing::Values(Constants::minimax_half, Constants::minimax),
                       ::testing::Values(Normalisation::patent, Normalisation::energy,
                                         Normalisation::none, Normalisation::device_energy),
                       ::testing::Values(Saturation::clamp)),
    combination_name);
INSTANTIATE_TEST_SUITE_P(
    Literal, ExhaustiveConstants,
    ::testing::Combine(::testing::Values(Constants::minimax_half, Constants::minimax),
                       ::testing::Values(Normalisation::none), ::testing::Values(Saturation::literal)),
    combination_name);
INSTANTIATE_TEST_SUITE_P(
    DeviceEnergy, ExhaustiveConstants,
    ::testing::Combine(::testing::Values(Constants::patent), ::testing::Values(Normalisation::device_energy),
                       ::testing::Values(Saturation::clamp)),
    combination_name);

// pin = core = TLM on the --sweep grid (1021 cos values × every n).
class ModelSweep : public ::testing::TestWithParam<std::tuple<Constants, tb::Model>> {};

TEST_P(ModelSweep, ModelEqualsCoreBitForBitAndMeetsTheBounds) {
  tb::RunSettings settings;
  settings.model = std::get<1>(GetParam());
  settings.config.constants = std::get<0>(GetParam());
  settings.config.normalisation = Normalisation::device_energy;
  const Core core(settings.config);
  tb::SweepSource sweep(core.formats(), {255, 128, 1});
  tb::Scoreboard scoreboard(settings.config);
  std::vector<tb::Stimulus> stimuli;
  std::size_t mismatches = 0;
  std::string first_mismatch;

  const testing_support::OperationShard shard = testing_support::operation_shard();
  const tb::OperandSource source = testing_support::sharded_sweep(sweep, stimuli, shard);
  const tb::ResultSink sink = [&](const std::vector<Operands>& chunk,
                                  const std::vector<Result>& results,
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
  tb::run_operations(settings, source, sink);

  const tb::Summary& s = scoreboard.summary();
  std::ostringstream text;
  tb::RunDescription run;
  run.model = settings.model == tb::Model::pin ? "pin" : "tlm";
  run.config = settings.config;
  tb::write_summary_text(text, s, run, -1);
  std::cout << text.str() << std::flush;
  EXPECT_EQ(s.count, 1021u * shard.covered(n_min, n_max));
  EXPECT_EQ(mismatches, 0u) << "first at " << first_mismatch;
  EXPECT_EQ(s.failures, 0u) << text.str();
}

INSTANTIATE_TEST_SUITE_P(
    Minimax, ModelSweep,
    ::testing::Combine(::testing::Values(Constants::minimax_half, Constants::minimax),
                       ::testing::Values(tb::Model::pin, tb::Model::tlm)),
    [](const auto& info) {
      std::string name = std::string(to_string(std::get<0>(info.param))) +
                         (std::get<1>(info.param) == tb::Model::pin ? "_pin" : "_tlm");
      for (char& ch : name)
        if (ch == '-') ch = '_';
      return name;
    });

}  // namespace
}  // namespace specular
