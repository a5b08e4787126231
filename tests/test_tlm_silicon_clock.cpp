// The TLM `lt` target at the silicon clock period (modules/include/specular/tlm/
// silicon_clock.h): its annotation scales with the period, 2.5 periods for START and
// 2.5 + 2·(k − 1) for a batch of k, here 2.5 × 37.5 = 93.75 ns and 20.5 × 37.5 =
// 768.75 ns, computed by hand from the spec's timing table.
#include <gtest/gtest.h>

#include <cstdint>

#include "specular/tlm/silicon_clock.h"
#include "support/tlm_bench.h"

namespace specular {
namespace {

using namespace tlm_testing;

TEST(TlmSiliconClock, PeriodIsTstaRoundedUpToHalfANanosecond) {
  // T_sta of docs/silicon.md: 37.18 ns; the setting is the next multiple of 0.5 ns.
  EXPECT_GE(kOsu018ClockPeriodNs, 37.18);
  EXPECT_LT(kOsu018ClockPeriodNs - 37.18, 0.5);
  EXPECT_EQ(kOsu018ClockPeriodNs * 2, static_cast<int>(kOsu018ClockPeriodNs * 2));
}

TEST(TlmSiliconClock, LtAnnotationScalesWithTheSiliconPeriod) {
  run(
      {Kind::lt},
      [](TlmBench& b) {
        Endpoint& e = b.at(0);
        sc_time annotated;
        ASSERT_EQ(e.write(Reg::cos, 50000, &annotated), tlm::TLM_OK_RESPONSE);
        ASSERT_EQ(e.write(Reg::control, control_bits::start, &annotated), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, sc_time(93.75, SC_NS)) << "2.5 periods of 37.5 ns";
        b.until(sc_time(200, SC_NS));
        std::uint32_t cos[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 65536};
        ASSERT_EQ(e.transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), cos, 40, 0,
                              nullptr, 0, &annotated),
                  tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(annotated, sc_time(768.75, SC_NS)) << "2.5 + 2 x 9 periods of 37.5 ns";
      },
      Config{}, osu018_clock_period());
}

}  // namespace
}  // namespace specular
