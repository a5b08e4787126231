// The bare-metal example (examples/firmware_rv32/main.c, issue 47) built for interrupts
// through a PLIC (-DEXAMPLE_WAIT_IRQ: docs/integration/riscv_vp.md's wiring), run on the
// host against each TLM target with a model of a SiFive-layout PLIC between done_irq and
// the hart (tests/support/firmware_example_host.h). It must pass its own check, and the
// PLIC must have been set up as section 10 says: priority above threshold, the source
// enabled, every interrupt claimed and completed. Two platforms: one that syncs after
// each write to the IP, where the edge of the polled operation is in the PLIC before the
// firmware enables it, so the firmware must claim and complete it first; and a decoupled
// one (1 us quantum), where that edge arrives later, at the first wfi, and the handler
// must find STATUS.DONE to tell a real interrupt from it. A firmware that skips the set-up
// sleeps in wfi for ever (the PLIC never forwards the source) and fails.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <tuple>

#include "support/firmware_example_host.h"

namespace specular {
namespace {

using example_host::Kind;

class FirmwareExampleIrqPlic : public testing::TestWithParam<std::tuple<Kind, bool>> {};

TEST_P(FirmwareExampleIrqPlic, SetsUpThePlicClaimsAndCompletesAndPasses) {
  const bool sync_after_writes = std::get<1>(GetParam());
  const example_host::Hart& hart = example_host::run_example(std::get<0>(GetParam()), true, sync_after_writes);
  std::cout << hart.console;
  example_host::expect_passed(hart);
  EXPECT_NE(hart.console.find("interrupt through the PLIC at 0x0c000000 source 1\n"), std::string::npos);
  EXPECT_NE(hart.console.find("pixels (by interrupt, "), std::string::npos);
  const firmware_targets::Plic& plic = hart.plic;
  EXPECT_GT(plic.priority, plic.threshold);
  EXPECT_NE(plic.enable & (1u << firmware_targets::Plic::source), 0u);
  if (sync_after_writes) {
    EXPECT_GE(plic.claims_before_interrupts_on, 1u) << "the source left pending by polling was not claimed first";
  }
  EXPECT_GE(example_interrupts, 1u);
  EXPECT_EQ(plic.claims, plic.claims_before_interrupts_on + example_interrupts + example_spurious_interrupts);
  EXPECT_EQ(plic.completes, plic.claims) << "a claim was not completed";
  EXPECT_FALSE(plic.in_service);
  EXPECT_EQ(plic.other_accesses, 0u);
}

std::string plic_test_name(const testing::TestParamInfo<std::tuple<Kind, bool>>& info) {
  return firmware_targets::target_name(std::get<0>(info.param)) +
         (std::get<1>(info.param) ? "_sync_after_writes" : "_decoupled");
}

INSTANTIATE_TEST_SUITE_P(Targets, FirmwareExampleIrqPlic,
                         testing::Combine(testing::Values(Kind::lt, Kind::pin, Kind::rtl, Kind::rtl_sync, Kind::axi),
                                          testing::Bool()),
                         plic_test_name);

}  // namespace
}  // namespace specular
