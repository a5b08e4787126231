// The bare-metal example (examples/firmware_rv32/main.c, issue 47) built polled (the row through BATCH_COS word by word, waiting on STATUS),
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

class FirmwareExamplePolled : public testing::TestWithParam<Kind> {};

TEST_P(FirmwareExamplePolled, ChecksEveryResultAgainstCoreAndPasses) {
  const example_host::Hart& hart = example_host::run_example(GetParam());
  std::cout << hart.console;
  example_host::expect_passed(hart);
  EXPECT_NE(hart.console.find("row of 8 pixels (polled): pins 24-26 equal to Core\n"), std::string::npos);
  EXPECT_EQ(example_interrupts, 0u);
}

INSTANTIATE_TEST_SUITE_P(Targets, FirmwareExamplePolled,
                         testing::Values(Kind::lt, Kind::pin, Kind::rtl, Kind::rtl_sync, Kind::axi),
                         example_host::kind_name);

}  // namespace
}  // namespace specular
