// The fourth implementation behind the TLM socket, `rtl-sync` (the verilated synchronous
// variant clocked inside b_transport), against `lt`: the same bits in every register —
// pins 24–26, register 1, register 9 after each pass, ROM 38, multiplier 39 — on
// random single operations under each policy and on a sampled sweep through the batch
// window; and the cycles it annotates are the variant's own timing table (docs/rtl.md):
// 2 periods for START, 2·k for a batch of k (one result every 2 T), not the drawn
// device's 2.5 + 2·(k − 1).
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

class TlmRtlSyncRandom : public testing_support::DevicePolicyTest {};

TEST_P(TlmRtlSyncRandom, SingleOperationsAgreeWithLtInEveryRegister) {
  const Config config = this->config();
  try {
    const Core core(config);
  } catch (const std::invalid_argument&) {  // refused by the core: by the target too
    EXPECT_THROW(SpecularRtlSyncTarget target("refused", config), std::invalid_argument);
    return;
  }
  constexpr int operations = 1000;
  int compared = 0;
  run(
      {Kind::lt, Kind::rtl_sync},
      [&](TlmBench& b) {
        std::mt19937_64 random(20261202);
        std::uniform_int_distribution<code_t> cos(0, 65536), n(1, 1000), rgb(0, 255);
        Operands op;
        for (int i = 0; i < operations; ++i) {
          op.cos = i % 10 == 0 ? 65536 - i / 10 % 4 : cos(random);
          if (i % 7 != 0) op.n = n(random);
          if (i % 7 != 0) op.rgb = {rgb(random), rgb(random), rgb(random)};
          const Result lt = b[Kind::lt].driver.compute_inspected(op);
          const Result sync = b[Kind::rtl_sync].driver.compute_inspected(op);
          ASSERT_EQ(sync.reg1, op.cos) << i;
          ASSERT_EQ(sync.reg9_pass1, lt.reg9_pass1) << i;
          ASSERT_EQ(sync.reg9_pass2, lt.reg9_pass2) << i;
          ASSERT_EQ(sync.rom38_k, lt.rom38_k) << i;
          ASSERT_EQ(sync.norm39, lt.norm39) << i;
          ASSERT_EQ(sync.out, lt.out) << i;
          ++compared;
        }
      },
      config);
  EXPECT_EQ(compared, operations);
}

INSTANTIATE_TEST_SUITE_P(Devices, TlmRtlSyncRandom, testing_support::every_device(),
                         testing_support::device_name);

TEST(TlmRtlSync, SampledSweepThroughTheBatchWindowEqualsLt) {
  long compared = 0;
  run({Kind::lt, Kind::rtl_sync}, [&](TlmBench& b) {
    const Formats f;
    std::vector<std::uint32_t> cos;
    for (const code_t c : testing_support::cos_codes(f, 1024)) cos.push_back(static_cast<std::uint32_t>(c));
    std::vector<std::int32_t> lt(3 * cos.size()), sync(3 * cos.size());
    for (unsigned n = 1; n <= 1000; n += 9) {
      const std::array<code_t, 3> rgb{255, 128 + n % 128, n % 256};
      b[Kind::lt].driver.compute_batch(n, rgb, cos.data(), cos.size(), lt.data());
      b[Kind::rtl_sync].driver.compute_batch(n, rgb, cos.data(), cos.size(), sync.data());
      for (std::size_t i = 0; i < cos.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
          ASSERT_EQ(sync[3 * i + ch], lt[3 * i + ch]) << "cos code " << cos[i] << ", n " << n;
          ++compared;
        }
    }
  });
  EXPECT_EQ(compared, 112 * 76 * 3);
}

// The annotation, counted from the variant's clock edges: 2 T for START, 2·k T for a
// batch of k.
TEST(TlmRtlSync, AnnotatesTheVariantsOwnLatency) {
  const sc_core::sc_time period(8, SC_NS);
  run(
      {Kind::rtl_sync},
      [&](TlmBench& b) {
        Endpoint& e = b.at(0);
        sc_core::sc_time annotated;
        ASSERT_EQ(e.write(Reg::cos, 50000, &annotated), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, sc_core::SC_ZERO_TIME) << "register writes take no time";
        ASSERT_EQ(e.write(Reg::control, control_bits::start, &annotated), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, period * 2.0);
        for (std::uint32_t k : {1u, 2u, 10u, 256u}) {
          std::vector<std::uint32_t> cos(k);
          for (std::uint32_t i = 0; i < k; ++i) cos[i] = (i * 257) % 65537;
          ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), cos.data(),
                                4 * k, 0, nullptr, 0, &annotated),
                    tlm::TLM_OK_RESPONSE);
          EXPECT_EQ(annotated, period * (2.0 * k)) << "batch of " << k;
        }
      },
      Config{}, period);
}

}  // namespace
}  // namespace specular
