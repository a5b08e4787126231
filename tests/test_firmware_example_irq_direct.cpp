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
  EXPECT_TRUE(hart.finished) << "the example never returned (halted: " << hart.halted << ")";
  EXPECT_EQ(hart.exit_status, 0) << hart.console;
  EXPECT_NE(hart.console.find("\nPASS: every result equal to Core\n"), std::string::npos) << hart.console;
  EXPECT_NE(hart.console.find("refusal: N = 1001 trapped (mcause 7, mtval 0x50000024) and skipped; "
                              "specular_check_error: cause 2 (N out of range), ERROR_ADDRESS 0x00000024\n"),
            std::string::npos)
      << hart.console;
  EXPECT_EQ(hart.faults, 1u);
  EXPECT_EQ(example_bus_faults, 1u);
  EXPECT_EQ(hart.bad_resumes, 0u) << "the trap handler did not skip the faulting store";
  EXPECT_NE(hart.console.find("pixels (by interrupt, "), std::string::npos);
  EXPECT_GE(example_interrupts, 1u) << "the row's wait ended without an interrupt";
  EXPECT_GE(hart.edges_taken, 1u);
}

INSTANTIATE_TEST_SUITE_P(Targets, FirmwareExampleIrqDirect,
                         testing::Values(Kind::lt, Kind::pin, Kind::rtl, Kind::rtl_sync),
                         example_host::kind_name);

}  // namespace
}  // namespace specular
