// The bare-metal example (examples/firmware_rv32) linked to an RV32 ELF as ctest's
// firmware_rv32_example_elf_* links it, into the test's scratch folder, for the RV32 hart
// tests (tests/test_firmware_example_rv32*.cpp). Needs SPECULAR_SOURCE_DIR and
// SPECULAR_EXAMPLE_EXPECTED_DIR (tests/CMakeLists.txt defines them).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "installed_package.h"
#include "scratch.h"
#include "subprocess.h"

namespace specular {
namespace testing_support {

/// Links the example's `variant` (poll, irq, irq_direct) with `extra` more compiler
/// arguments (e.g. " -DEXAMPLE_WATCHDOG_TICKS=1000u"); returns the ELF's path.
inline std::filesystem::path link_rv32_example(const std::string& variant, const std::string& extra = "") {
  const std::filesystem::path dir = scratch_subdir("elf");
  const std::string source = SPECULAR_SOURCE_DIR, example = source + "/examples/firmware_rv32";
  std::string defines;
  if (variant != "poll") defines += " -DEXAMPLE_WAIT_IRQ";
  if (variant == "irq_direct") defines += " -DEXAMPLE_IRQ_DIRECT";
  const std::filesystem::path elf = dir / "firmware_rv32.elf";
  const auto outcome = run_command(
      "riscv64-unknown-elf-gcc -march=rv32imac -mabi=ilp32 --specs=picolibc.specs -std=c99 -Wall -Wextra"
      " -Wpedantic -Werror -ffreestanding -Os -nostartfiles -Wl,--no-warn-rwx-segments -T " +
          shell_quoted(example + "/link.ld") + " -I" + shell_quoted(source + "/firmware/include") + " -I" +
          shell_quoted(example) + " -I" + shell_quoted(SPECULAR_EXAMPLE_EXPECTED_DIR) + defines + extra + " " +
          shell_quoted(example + "/startup.S") + " " + shell_quoted(example + "/main.c") + " " +
          shell_quoted(source + "/firmware/src/specular_driver.c") + " -o " + shell_quoted(elf.string()),
      dir, "link");
  EXPECT_EQ(outcome.status, 0) << "(riscv64-unknown-elf-gcc and picolibc-riscv64-unknown-elf are in "
                                  "scripts/setup.sh)\n" << outcome.out << outcome.err;
  return elf;
}

}  // namespace testing_support
}  // namespace specular
