// The bare-metal example (examples/firmware_rv32/main.c, issue 47) built with done_irq straight to the hart (-DEXAMPLE_WAIT_IRQ -DEXAMPLE_IRQ_DIRECT: the row waits in wfi for the interrupt, its handler acknowledges),
// run on the host against each TLM target (tests/support/firmware_example_host.h): it
// must end with exit status 0 and its PASS line, having compared every result with the
// bits Core computed at build time (example_expected.h), and its refused store (N = 1001)
// must have trapped once, been skipped by its handler and reported by
// specular_check_error. The PLIC build is not run here: its PLIC is memory-mapped and
// the host has none (firmware_rv32_example_run_irq runs it on a VP).
#include <gtest/gtest.h>

#include <iostream>

#include "support/firmware_example_host.h"

namespace specular {
namespace {

using example_host::Kind;

class FirmwareExampleIrqDirect : public testing::TestWithParam<Kind> {};

TEST_P(FirmwareExampleIrqDirect, ChecksEveryResultAgainstCoreAndPasses) {
  const example_host::Hart& hart = example_host::run_example(GetParam());
  std::cout << hart.console;
  example_host::expect_passed(hart);
  EXPECT_NE(hart.console.find("pixels (by interrupt, "), std::string::npos);
  EXPECT_GE(example_interrupts, 1u) << "the row's wait ended without an interrupt";
  EXPECT_GE(hart.edges_taken, 1u);
}

INSTANTIATE_TEST_SUITE_P(Targets, FirmwareExampleIrqDirect,
                         testing::Values(Kind::lt, Kind::pin, Kind::rtl, Kind::rtl_sync, Kind::axi),
                         example_host::kind_name);

}  // namespace
}  // namespace specular
