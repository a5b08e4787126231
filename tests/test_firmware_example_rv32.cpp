// The bare-metal example's ELF itself (issue 47), as ctest's firmware_rv32_example_elf_*
// links it, run on a small RV32IMC hart (tests/support/rv32_hart.h: RAM at 0, the IP at
// 0x5000_0000, riscv-vp's intercepted write and exit, error responses as access faults)
// against the lt and rtl-sync targets: polled, through a PLIC (a model at 0x0C00_0000,
// source 1), and with done_irq straight to the hart. Each must exit 0 having printed its
// PASS line, its refused store trapped once (mcause 7, mtval 0x50000024) and skipped, and
// by interrupt at least one interrupt taken. This is not riscv-vp: it is an interpreter
// of the instructions the example uses, so that the shipped program, startup and trap
// entry included, is run somewhere; firmware_rv32_example_run_* runs it on a real VP.
#include <gtest/gtest.h>

#include <iostream>
#include <regex>
#include <string>
#include <tuple>

#include "support/installed_package.h"
#include "support/rv32_example_link.h"
#include "support/rv32_hart.h"
#include "support/subprocess.h"

namespace specular {
namespace {

using firmware_targets::Kind;
using testing_support::run_command;
using testing_support::shell_quoted;

using testing_support::link_rv32_example;

class FirmwareExampleRv32 : public testing::TestWithParam<std::tuple<Kind, std::string>> {};

TEST_P(FirmwareExampleRv32, TheElfPassesItsOwnCheckOnAnRv32Hart) {
  const Kind kind = std::get<0>(GetParam());
  const std::string variant = std::get<1>(GetParam());
  const std::filesystem::path elf = link_rv32_example(variant);
  ASSERT_TRUE(std::filesystem::exists(elf));
  static std::unique_ptr<firmware_targets::Rv32Hart> hart;  // alive until exit, as SystemC wants
  hart = std::make_unique<firmware_targets::Rv32Hart>(
      "hart", kind, variant == "irq" ? firmware_targets::IrqWiring::plic : firmware_targets::IrqWiring::hart, elf.string());
  // The instructions specular_shade takes for the row (issue 47: batches from a CPU).
  const auto nm = run_command("riscv64-unknown-elf-nm " + shell_quoted(elf), elf.parent_path(), "nm");
  const std::size_t at = nm.out.find(" T specular_shade\n");
  if (at != std::string::npos && at >= 8) hart->probe_entry = static_cast<std::uint32_t>(std::stoul(nm.out.substr(at - 8, 8), nullptr, 16));
  sc_core::sc_start();
  std::cout << hart->console << "(" << hart->instructions << " instructions, " << hart->interrupts
            << " interrupts, " << hart->faults << " faults; specular_shade: " << hart->probe_instructions
            << " instructions for the row)\n";
  EXPECT_TRUE(hart->exited) << "the program did not exit: " << hart->error << " at pc " << hart->pc;
  EXPECT_EQ(hart->exit_code, 0) << hart->console;
  EXPECT_NE(hart->console.find("\nPASS: every result equal to Core\n"), std::string::npos) << hart->console;
  EXPECT_NE(hart->console.find("refusal: N = 1001 trapped (mcause 7, mtval 0x50000024) and skipped; "
                               "specular_check_error: cause 2 (N out of range)"),
            std::string::npos);
  EXPECT_EQ(hart->faults, 1u);
  EXPECT_EQ(hart->timer_interrupts, 0u) << "the watchdog fired";
  if (variant == "poll") {
    EXPECT_EQ(hart->interrupts, 0u);
  } else {
    EXPECT_GE(hart->interrupts, 1u);
    EXPECT_NE(hart->console.find("pixels (by interrupt, "), std::string::npos);
  }
  if (variant == "irq") {
    EXPECT_EQ(hart->plic.completes, hart->plic.claims);
    EXPECT_GT(hart->plic.priority, hart->plic.threshold);
  }
}

// riscv-vp raises a store page fault (mcause 15) for a failed transaction, where the
// specification's access fault is 7: the example's handler skips it just the same.
TEST(FirmwareExampleRv32Faults, APageFaultAsRiscvVpRaisesItIsSkippedToo) {
  const std::filesystem::path elf = link_rv32_example("poll");
  ASSERT_TRUE(std::filesystem::exists(elf));
  static std::unique_ptr<firmware_targets::Rv32Hart> hart;  // alive until exit, as SystemC wants
  hart = std::make_unique<firmware_targets::Rv32Hart>("hart", Kind::lt, firmware_targets::IrqWiring::hart, elf.string());
  hart->load_fault = 13u;
  hart->store_fault = 15u;
  sc_core::sc_start();
  std::cout << hart->console;
  EXPECT_TRUE(hart->exited) << hart->error;
  EXPECT_EQ(hart->exit_code, 0) << hart->console;
  EXPECT_NE(hart->console.find("refusal: N = 1001 trapped (mcause 15, mtval 0x50000024) and skipped"),
            std::string::npos)
      << hart->console;
  EXPECT_NE(hart->console.find("\nPASS: every result equal to Core\n"), std::string::npos);
}

// Issue 61: built with the platform's energy counter (EXAMPLE_ENERGY_COUNTER), the example
// prints the row's energy: one operation per pixel, each near the gate-level mean of the
// synchronous device (4 789 pJ, docs/design_space/energy_per_result.md) plus the bus and
// the clocks the row took.
TEST(FirmwareExampleRv32Energy, TheRowPrintsItsEnergyFromThePlatformsCounter) {
  const std::filesystem::path elf = link_rv32_example("poll", " -DEXAMPLE_ENERGY_COUNTER=0x50010000u");
  ASSERT_TRUE(std::filesystem::exists(elf));
  static std::unique_ptr<firmware_targets::Rv32Hart> hart;  // alive until exit, as SystemC wants
  hart = std::make_unique<firmware_targets::Rv32Hart>("hart", Kind::lt, firmware_targets::IrqWiring::hart, elf.string());
  sc_core::sc_start();
  std::cout << hart->console;
  EXPECT_EQ(hart->exit_code, 0) << hart->console;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(hart->console, m,
                                std::regex(R"(energy of the row \(the platform's counter at 0x50010000\): ([0-9]+) pJ per pixel, ([0-9]+) nJ for the row of ([0-9]+) pixels, ([0-9]+) operations)")))
      << hart->console;
  const double per_pixel = std::stod(m[1]), row_nj = std::stod(m[2]);
  const long pixels = std::stol(m[3]), operations = std::stol(m[4]);
  EXPECT_NE(hart->console.find("row of " + std::to_string(pixels) + " pixels (polled)"), std::string::npos);
  EXPECT_EQ(operations, pixels);
  EXPECT_NEAR(row_nj * 1000, per_pixel * static_cast<double>(pixels), 1000 + per_pixel);  // integer division
  EXPECT_GT(per_pixel, 0.9 * 4789);
  // At most what the whole run's work costs at the gate-level figures (docs/rtl_ip.md:
  // 313 pJ a read, 493 a write, 147 an idle clock, here 10 ns): the IP's clock runs
  // while the hart computes, and a slow hart makes a pixel cost mostly clocks.
  const energy::EnergyTally whole = hart->target->energy();
  const double bound = 2 * 4789.0 * static_cast<double>(whole.operations) + 313.0 * static_cast<double>(whole.reads) +
                       493.0 * static_cast<double>(whole.writes) + 147.0 * sc_core::sc_time_stamp().to_seconds() / 10e-9;
  EXPECT_LT(per_pixel * static_cast<double>(pixels), bound);
}

std::string rv32_test_name(const testing::TestParamInfo<std::tuple<Kind, std::string>>& info) {
  return firmware_targets::target_name(std::get<0>(info.param)) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Targets, FirmwareExampleRv32,
                         testing::Combine(testing::Values(Kind::lt, Kind::rtl_sync, Kind::axi),
                                          testing::Values(std::string("poll"), std::string("irq"),
                                                          std::string("irq_direct"))),
                         rv32_test_name);

}  // namespace
}  // namespace specular
