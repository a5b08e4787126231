// The bare-metal example's ELF (examples/firmware_rv32) linked at test time into the
// test's own folder, with the expected bits of this build, as tests/firmware/CMakeLists.txt
// links it (issue 47); for the tests that run it on tests/support/rv32_hart.h. The
// including program defines SPECULAR_SOURCE_DIR and SPECULAR_EXAMPLE_EXPECTED_DIR.
#ifndef SPECULAR_TESTS_SUPPORT_FIRMWARE_EXAMPLE_ELF_H
#define SPECULAR_TESTS_SUPPORT_FIRMWARE_EXAMPLE_ELF_H

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "installed_package.h"
#include "scratch.h"
#include "subprocess.h"

namespace specular {
namespace testing_support {

/// Links the example's `variant` (poll, irq: through a PLIC, irq_direct: done_irq to the
/// hart); returns the ELF's path (a failed link is a test failure, and no file).
inline std::filesystem::path link_example(const std::string& variant) {
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
          shell_quoted(example) + " -I" + shell_quoted(SPECULAR_EXAMPLE_EXPECTED_DIR) + defines + " " +
          shell_quoted(example + "/startup.S") + " " + shell_quoted(example + "/main.c") + " " +
          shell_quoted(source + "/firmware/src/specular_driver.c") + " -o " + shell_quoted(elf.string()),
      dir, "link");
  EXPECT_EQ(outcome.status, 0) << "(riscv64-unknown-elf-gcc and picolibc-riscv64-unknown-elf are in "
                                  "scripts/setup.sh)\n" << outcome.out << outcome.err;
  return elf;
}

}  // namespace testing_support
}  // namespace specular

#endif  // SPECULAR_TESTS_SUPPORT_FIRMWARE_EXAMPLE_ELF_H
