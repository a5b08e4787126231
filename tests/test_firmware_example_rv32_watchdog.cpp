// The example's watchdog (issue 60): the interrupt builds' ELFs run on the RV32 hart
// (tests/support/rv32_hart.h) wired the other way, so that done_irq never comes as the
// build expects, must print a FAIL line naming what they waited on and exit with 30
// through the exit call, once the bound (EXAMPLE_WATCHDOG_TICKS of the CLINT's mtime,
// microseconds of simulated time on this hart as on riscv-vp) has passed and not before:
//   - the PLIC build with done_irq straight to the hart beside an idle PLIC: the line
//     re-enters the handler for ever (nothing to claim, nothing acknowledged), which
//     starves the timer's interrupt; the handler's own check ends it;
//   - the direct build with done_irq through a PLIC it never programs: nothing wakes its
//     wfi but the watchdog's timer;
//   - the PLIC build on a hart with no PLIC at all: the first PLIC store faults, an
//     unexpected trap, exit 40, the line naming the missing PLIC;
//   - the PLIC build for context 1 with SiFive's strides on riscv-vp's packed layout
//     (and, passing, with riscv-vp's strides).
// The passing runs (tests/test_firmware_example_rv32.cpp) check the timer never fires.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>
#include <string>

#include "support/rv32_example_link.h"
#include "support/rv32_hart.h"

namespace specular {
namespace {

using firmware_targets::Kind;
using firmware_targets::Rv32Hart;
using firmware_targets::IrqWiring;

constexpr double default_bound_us = 65536.0;  // main.c's EXAMPLE_WATCHDOG_TICKS, at 1 tick per us

/// The PLIC's layout on the hart: the context the firmware must use, bytes per context.
struct PlicLayout {
  std::uint32_t context = 0, enable_stride = 0x80u, context_stride = 0x1000u;
};

/// Runs `variant` (with `extra` compiler arguments) on the lt target with done_irq wired
/// as `wiring`; the hart stays alive until exit, as SystemC wants.
Rv32Hart& run(const std::string& variant, IrqWiring wiring, const std::string& extra = "", PlicLayout layout = {}) {
  const std::filesystem::path elf = testing_support::link_rv32_example(variant, extra);
  static std::unique_ptr<Rv32Hart> hart;
  hart = std::make_unique<Rv32Hart>("hart", Kind::lt, wiring, elf.string());
  hart->limit = 50000000;  // the storm below takes about 7 million instructions
  hart->plic.context = layout.context;
  hart->plic.enable_stride = layout.enable_stride;
  hart->plic.context_stride = layout.context_stride;
  sc_core::sc_start();
  std::cout << hart->console << "(" << hart->instructions << " instructions, " << hart->interrupts
            << " external and " << hart->timer_interrupts << " timer interrupts, stopped at "
            << sc_core::sc_time_stamp() << ")\n";
  return *hart;
}

/// Exit 30 through the exit call, the polled part passed first, the FAIL line whole.
void expect_watchdog(const Rv32Hart& hart, const std::string& fail_line) {
  EXPECT_TRUE(hart.exited) << "the program did not exit: " << hart.error << " at pc " << hart.pc;
  EXPECT_EQ(hart.exit_code, 30) << hart.console;
  EXPECT_NE(hart.console.find("one operation (polled): pins 24-26 and register 9 equal to Core\n"),
            std::string::npos)
      << hart.console;
  EXPECT_NE(hart.console.find("\n" + fail_line + "\n"), std::string::npos) << hart.console;
  EXPECT_EQ(hart.console.find("PASS"), std::string::npos) << hart.console;
}

TEST(FirmwareExampleRv32Watchdog, ThePlicBuildWithDoneIrqStraightToTheHartFailsNamingThePlicSource) {
  const Rv32Hart& hart = run("irq", IrqWiring::hart_beside_plic);
  expect_watchdog(hart, "FAIL: no done_irq interrupt within 65536 mtime ticks (waited on source 1 of the PLIC at "
                        "0x0c000000, context 0; " +
                            std::to_string(hart.interrupts) +
                            " external interrupts had nothing to claim: done_irq wired straight to the hart? that "
                            "is the irq_direct build)");
  EXPECT_GT(hart.interrupts, 1000u) << "the line should re-enter the handler until the watchdog";
  EXPECT_EQ(hart.timer_interrupts, 0u) << "the external interrupt outranks the timer's";
  EXPECT_EQ(hart.plic.claims, 0u);
  // Not before the bound: the row started after about 20 us of simulated time.
  EXPECT_GE(sc_core::sc_time_stamp(), sc_core::sc_time(default_bound_us, sc_core::SC_US));
  EXPECT_LT(sc_core::sc_time_stamp(), sc_core::sc_time(default_bound_us + 1000.0, sc_core::SC_US));
}

TEST(FirmwareExampleRv32Watchdog, TheDirectBuildWithDoneIrqThroughAPlicFailsNamingTheExternalInterrupt) {
  const Rv32Hart& hart = run("irq_direct", IrqWiring::plic);
  expect_watchdog(hart, "FAIL: no done_irq interrupt within 65536 mtime ticks (waited on the machine external "
                        "interrupt, done_irq straight to the hart; none came: done_irq wired to a PLIC? that is the "
                        "irq build)");
  EXPECT_EQ(hart.interrupts, 0u);
  EXPECT_EQ(hart.timer_interrupts, 1u) << "only the watchdog's timer wakes the wfi";
  EXPECT_TRUE(hart.plic.pending) << "done_irq reached the PLIC, which nobody programmed";
  EXPECT_GE(sc_core::sc_time_stamp(), sc_core::sc_time(default_bound_us, sc_core::SC_US));
  EXPECT_LT(sc_core::sc_time_stamp(), sc_core::sc_time(default_bound_us + 1000.0, sc_core::SC_US));
}

// The bound is a build option: 500 ticks fire after 0.5 ms instead of 65.5 ms.
TEST(FirmwareExampleRv32Watchdog, TheBoundIsABuildOption) {
  const Rv32Hart& hart = run("irq_direct", IrqWiring::plic, " -DEXAMPLE_WATCHDOG_TICKS=500u");
  expect_watchdog(hart, "FAIL: no done_irq interrupt within 500 mtime ticks (waited on the machine external "
                        "interrupt, done_irq straight to the hart; none came: done_irq wired to a PLIC? that is the "
                        "irq build)");
  EXPECT_GE(sc_core::sc_time_stamp(), sc_core::sc_time(500.0, sc_core::SC_US));
  EXPECT_LT(sc_core::sc_time_stamp(), sc_core::sc_time(1000.0, sc_core::SC_US));
}

TEST(FirmwareExampleRv32Watchdog, ThePlicBuildWithNoPlicOnTheBusFailsAtItsFirstPlicStore) {
  const Rv32Hart& hart = run("irq", IrqWiring::hart);
  EXPECT_TRUE(hart.exited) << hart.error;
  EXPECT_EQ(hart.exit_code, 40) << hart.console;
  // The priority of source 1 (offset 4) is the first PLIC register written.
  EXPECT_NE(hart.console.find(", mtval 0x0c000004 (no PLIC at EXAMPLE_PLIC_BASE? with done_irq straight to the "
                              "hart, that is the irq_direct build)\n"),
            std::string::npos)
      << hart.console;
  EXPECT_NE(hart.console.find("FAIL: unexpected trap, mcause 0x00000007 at "), std::string::npos) << hart.console;
}

// The PLIC's context and strides are build options (issue 60): riscv-vp's FE310_PLIC
// (hifive-vp: enables 8 bytes, threshold/claim 8 bytes per context) at context 1.
constexpr PlicLayout riscv_vp_context_1{1u, 8u, 8u};

TEST(FirmwareExampleRv32PlicLayout, ThePlicBuildForRiscvVpsStridesPassesAtContextOne) {
  const std::string defines = " -DEXAMPLE_PLIC_CONTEXT=1u -DEXAMPLE_PLIC_ENABLE_STRIDE=8u -DEXAMPLE_PLIC_CONTEXT_STRIDE=8u";
  const Rv32Hart& hart = run("irq", IrqWiring::plic, defines, riscv_vp_context_1);
  EXPECT_TRUE(hart.exited) << hart.error;
  EXPECT_EQ(hart.exit_code, 0) << hart.console;
  EXPECT_NE(hart.console.find("\nPASS: every result equal to Core\n"), std::string::npos) << hart.console;
  EXPECT_GE(hart.plic.claims, 1u);
  EXPECT_EQ(hart.plic.completes, hart.plic.claims);
  EXPECT_EQ(hart.plic.other_accesses, 0u);
}

// SiFive's strides (the defaults) on that PLIC: the enable and threshold land in other
// contexts' registers, the source is never enabled for context 1, and the watchdog says so.
TEST(FirmwareExampleRv32PlicLayout, SiFivesStridesOnRiscvVpsPlicFireTheWatchdogNamingTheContext) {
  const Rv32Hart& hart = run("irq", IrqWiring::plic, " -DEXAMPLE_PLIC_CONTEXT=1u", riscv_vp_context_1);
  expect_watchdog(hart, "FAIL: no done_irq interrupt within 65536 mtime ticks (waited on source 1 of the PLIC at "
                        "0x0c000000, context 1; no external interrupt came: done_irq on another source, or the "
                        "context or the PLIC's strides not the platform's?)");
  EXPECT_EQ(hart.plic.enable, 0u);
  EXPECT_GT(hart.plic.other_accesses, 0u);
  EXPECT_EQ(hart.timer_interrupts, 1u);
}

}  // namespace
}  // namespace specular
