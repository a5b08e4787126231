// The verilated twins behind the TLM socket, clocked inside b_transport — `rtl` (the
// drawn device) and `rtl-sync` (the synchronous variant) — against `lt`: the same bits in
// every register — pins 24–26, register 1, register 9 after each pass, ROM 38,
// multiplier 39 — on random single operations under each policy and on a sampled sweep
// through the batch window; and the cycles each annotates, counted from its own clock
// edges, are its timing table's: `rtl` 2.5 periods for START and 2.5 + 2·(k − 1) for a
// batch of k (the spec's table, SpecularTarget::latency_cycles, what `lt` annotates);
// `rtl-sync` 2 and 2·k (one result every 2 T, docs/rtl.md).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "support/accuracy_sweep.h"
#include "support/policies.h"
#include "support/tlm_bench.h"

namespace specular {
namespace {

using namespace tlm_testing;

/// Start to 35↑ of the first result, in periods (each further streamed result: 2 T).
constexpr double drawn_first_periods = 2.5;
constexpr double sync_first_periods = 2.0;

/// 1 000 random operations on `lt` and on the twin `kind`, every register compared. The
/// devices the core refuses, the twin's target (`Target`) refuses too.
template <class Target>
void single_operations_agree_with_lt(const Config& config, Kind kind, std::uint64_t seed) {
  try {
    const Core core(config);
  } catch (const std::invalid_argument&) {  // refused by the core: by the target too
    EXPECT_THROW(Target target("refused", config), std::invalid_argument);
    return;
  }
  constexpr int operations = 1000;
  int compared = 0;
  run(
      {Kind::lt, kind},
      [&](TlmBench& b) {
        std::mt19937_64 random(seed);
        std::uniform_int_distribution<code_t> cos(0, 65536), n(1, 1000), rgb(0, 255);
        Operands op;
        for (int i = 0; i < operations; ++i) {
          op.cos = i % 10 == 0 ? 65536 - i / 10 % 4 : cos(random);  // the last codes too
          if (i % 7 != 0) op.n = n(random);  // else n and R, G, B stay: no operand writes
          if (i % 7 != 0) op.rgb = {rgb(random), rgb(random), rgb(random)};
          const Result lt = b[Kind::lt].driver.compute_inspected(op);
          const Result twin = b[kind].driver.compute_inspected(op);
          ASSERT_EQ(twin.reg1, op.cos) << i;
          ASSERT_EQ(twin.reg9_pass1, lt.reg9_pass1) << i;
          ASSERT_EQ(twin.reg9_pass2, lt.reg9_pass2) << i;
          ASSERT_EQ(twin.rom38_k, lt.rom38_k) << i;
          ASSERT_EQ(twin.norm39, lt.norm39) << i;
          ASSERT_EQ(twin.out, lt.out) << i;
          ++compared;
        }
      },
      config);
  EXPECT_EQ(compared, operations);
}

/// Every 9th n × 76 cos codes through BATCH_COS / BATCH_OUT: the streamed operations.
void sampled_sweep_equals_lt(Kind kind) {
  long compared = 0;
  run({Kind::lt, kind}, [&](TlmBench& b) {
    const Formats f;
    std::vector<std::uint32_t> cos;
    for (const code_t c : testing_support::cos_codes(f, 1024)) cos.push_back(static_cast<std::uint32_t>(c));
    std::vector<std::int32_t> lt(3 * cos.size()), twin(3 * cos.size());
    for (unsigned n = 1; n <= 1000; n += 9) {
      const std::array<code_t, 3> rgb{255, 128 + n % 128, n % 256};
      b[Kind::lt].driver.compute_batch(n, rgb, cos.data(), cos.size(), lt.data());
      b[kind].driver.compute_batch(n, rgb, cos.data(), cos.size(), twin.data());
      for (std::size_t i = 0; i < cos.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
          ASSERT_EQ(twin[3 * i + ch], lt[3 * i + ch]) << "cos code " << cos[i] << ", n " << n;
          ++compared;
        }
    }
  });
  EXPECT_EQ(compared, 112 * 76 * 3);
}

/// The annotation: START takes `first` periods of the twin's clock, a batch of k
/// first + 2·(k − 1); register writes take no time.
void annotates_its_timing_table(Kind kind, double first) {
  const sc_core::sc_time period(8, SC_NS);
  run(
      {kind},
      [&](TlmBench& b) {
        Endpoint& e = b.at(0);
        sc_core::sc_time annotated;
        ASSERT_EQ(e.write(Reg::cos, 50000, &annotated), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, sc_core::SC_ZERO_TIME) << "register writes take no time";
        ASSERT_EQ(e.write(Reg::control, control_bits::start, &annotated), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, period * first);
        for (std::uint32_t k : {1u, 2u, 10u, 256u}) {
          std::vector<std::uint32_t> cos(k);
          for (std::uint32_t i = 0; i < k; ++i) cos[i] = (i * 257) % 65537;
          ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), cos.data(),
                                4 * k, 0, nullptr, 0, &annotated),
                    tlm::TLM_OK_RESPONSE);
          EXPECT_EQ(annotated, period * (first + 2.0 * (k - 1))) << "batch of " << k;
        }
      },
      Config{}, period);
}

// ---- rtl: the drawn device ---------------------------------------------------------

class TlmRtlRandom : public testing_support::DevicePolicyTest {};
TEST_P(TlmRtlRandom, SingleOperationsAgreeWithLtInEveryRegister) {
  single_operations_agree_with_lt<SpecularRtlTarget>(config(), Kind::rtl, 20261125);
}
INSTANTIATE_TEST_SUITE_P(Devices, TlmRtlRandom, testing_support::every_device(),
                         testing_support::device_name);

TEST(TlmRtl, SampledSweepThroughTheBatchWindowEqualsLt) { sampled_sweep_equals_lt(Kind::rtl); }
TEST(TlmRtl, AnnotatesTheCyclesTheTwinTook) { annotates_its_timing_table(Kind::rtl, drawn_first_periods); }

// ---- rtl-sync: the synchronous variant ---------------------------------------------

class TlmRtlSyncRandom : public testing_support::DevicePolicyTest {};
TEST_P(TlmRtlSyncRandom, SingleOperationsAgreeWithLtInEveryRegister) {
  single_operations_agree_with_lt<SpecularRtlSyncTarget>(config(), Kind::rtl_sync, 20261202);
}
INSTANTIATE_TEST_SUITE_P(Devices, TlmRtlSyncRandom, testing_support::every_device(),
                         testing_support::device_name);

TEST(TlmRtlSync, SampledSweepThroughTheBatchWindowEqualsLt) { sampled_sweep_equals_lt(Kind::rtl_sync); }
TEST(TlmRtlSync, AnnotatesTheVariantsOwnLatency) {
  annotates_its_timing_table(Kind::rtl_sync, sync_first_periods);
}

}  // namespace
}  // namespace specular
