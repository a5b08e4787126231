// The firmware targets of the installed package (issue 35): SpecularUnit::firmware (the
// C headers) and SpecularUnit::firmware_driver (the driver's source) taken by a C-only
// project with find_package(SpecularUnit CONFIG REQUIRED COMPONENTS firmware):
//   - on the host, with SystemC made unfindable, the program builds and runs the driver on
//     its default volatile accessors (tests/firmware/consumer/main.c);
//   - cross-compiled for rv32imac/ilp32 (riscv64-unknown-elf-gcc, picolibc) with
//     find_package(SpecularUnitFirmware CONFIG REQUIRED), the architecture-independent
//     package of the same targets, the driver builds into the firmware's library under
//     -Wpedantic -Werror.
// Each test installs this build into its own scratch folder, as test_package_systemc does.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/installed_package.h"
#include "support/scratch.h"
#include "support/subprocess.h"

namespace fs = std::filesystem;

namespace {

using specular::testing_support::cmake;
using specular::testing_support::install;
using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::scratch_subdir;
using specular::testing_support::shell_quoted;
using specular::testing_support::slurp;

const fs::path consumer = fs::path(SPECULAR_SOURCE_DIR) / "tests/firmware/consumer";
/// Arguments that leave no SystemC to find: no CMake package, no pkg-config.
const std::string no_systemc =
    " -DCMAKE_DISABLE_FIND_PACKAGE_SystemCLanguage=ON -DPKG_CONFIG_EXECUTABLE=/nonexistent/pkg-config";

TEST(FirmwarePackage, AHostCProgramRunsTheInstalledDriverWithoutSystemC) {
  const fs::path dir = scratch_subdir("host");
  const fs::path prefix = install(dir);
  // Make's generator whatever CMAKE_GENERATOR says (scripts/test.sh sets Ninja): its
  // build.make is read below.
  const Outcome configure = run_command(
      cmake() + " -G 'Unix Makefiles' -S " + shell_quoted(consumer) + " -B " + shell_quoted(dir / "build") +
          " -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix) + " -DCMAKE_C_COMPILER=gcc" + no_systemc,
      dir, "configure");
  ASSERT_EQ(configure.status, 0) << configure.out << configure.err;
  EXPECT_EQ(configure.out.find("-- SystemC"), std::string::npos) << "SystemC was looked for:\n" << configure.out;
  const Outcome build = run_command(cmake() + " --build " + shell_quoted(dir / "build"), dir, "build");
  ASSERT_EQ(build.status, 0) << build.out << build.err;
  // The driver's source came from the installed package, not the source tree.
  EXPECT_NE(slurp(dir / "build/CMakeFiles/firmware_app.dir/build.make")
                .find((prefix / "share/SpecularUnit/firmware/specular_driver.c").string()),
            std::string::npos);
  const Outcome run = run_command(shell_quoted(dir / "build/firmware_app"), dir, "app");
  EXPECT_EQ(run.status, 0) << "firmware_app's exit status names the step that failed (main.c)";
}

TEST(FirmwarePackage, ARv32FirmwareBuildCrossCompilesTheInstalledDriver) {
  const fs::path dir = scratch_subdir("rv32");
  const fs::path prefix = install(dir);
  const Outcome configure = run_command(
      cmake() + " -S " + shell_quoted(consumer) + " -B " + shell_quoted(dir / "build") +
          " -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix) +
          " -DCMAKE_SYSTEM_NAME=Generic -DCMAKE_SYSTEM_PROCESSOR=riscv32"
          " -DCMAKE_C_COMPILER=riscv64-unknown-elf-gcc"
          " '-DCMAKE_C_FLAGS=-march=rv32imac -mabi=ilp32 --specs=picolibc.specs -ffreestanding'"
          " -DCMAKE_TRY_COMPILE_TARGET_TYPE=STATIC_LIBRARY"
          " -DCMAKE_FIND_ROOT_PATH_MODE_PACKAGE=BOTH" + no_systemc,
      dir, "configure");
  ASSERT_EQ(configure.status, 0) << "(riscv64-unknown-elf-gcc and picolibc-riscv64-unknown-elf "
                                    "are in scripts/setup.sh)\n" << configure.out << configure.err;
  const Outcome build = run_command(cmake() + " --build " + shell_quoted(dir / "build") + " --verbose", dir, "build");
  ASSERT_EQ(build.status, 0) << build.out << build.err;
  EXPECT_NE(build.out.find("riscv64-unknown-elf-gcc"), std::string::npos);
  EXPECT_NE(build.out.find("-march=rv32imac"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "build/libfirmware_app.a"));
}

// Issue 47: the bare-metal example as the package installs it
// (share/SpecularUnit/firmware_rv32/, with the expected bits Core computed at build time),
// built from the install prefix alone with the installed toolchain files: three RV32 ELFs
// (polled, through a PLIC, straight to the hart) with rv32imac-picolibc.cmake, and the
// checking program as a Cortex-M4 library with cortex-m4-newlib.cmake. The driver's
// source is the installed one; no path of the source tree is used.
TEST(FirmwarePackage, TheInstalledExampleBuildsWithTheInstalledToolchainFiles) {
  const fs::path dir = scratch_subdir("example");
  const fs::path prefix = install(dir);
  const fs::path example = prefix / "share/SpecularUnit/firmware_rv32";
  const fs::path toolchains = prefix / "share/SpecularUnit/toolchains";
  ASSERT_TRUE(fs::exists(example / "example_expected.h")) << "the generated header is not installed";
  struct Build {
    const char* name;
    const char* toolchain;
    std::vector<std::string> products;
  };
  const Build builds[] = {
      {"rv32", "rv32imac-picolibc.cmake",
       {"firmware_rv32_poll.elf", "firmware_rv32_irq.elf", "firmware_rv32_irq_direct.elf"}},
      {"cortex_m4", "cortex-m4-newlib.cmake",
       {"libfirmware_rv32_poll.a", "libfirmware_rv32_irq.a", "libfirmware_rv32_irq_direct.a"}},
  };
  for (const Build& b : builds) {
    const fs::path build_dir = dir / b.name;
    const Outcome configure = run_command(
        cmake() + " -S " + shell_quoted(example) + " -B " + shell_quoted(build_dir) +
            " --toolchain " + shell_quoted(toolchains / b.toolchain) +
            " -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix) + no_systemc,
        dir, std::string("configure_") + b.name);
    ASSERT_EQ(configure.status, 0) << b.name << ":\n" << configure.out << configure.err;
    const Outcome build =
        run_command(cmake() + " --build " + shell_quoted(build_dir) + " --verbose", dir, std::string("build_") + b.name);
    ASSERT_EQ(build.status, 0) << b.name << ":\n" << build.out << build.err;
    for (const std::string& product : b.products)
      EXPECT_TRUE(fs::exists(build_dir / product)) << b.name << ": no " << product;
    EXPECT_NE(build.out.find((prefix / "share/SpecularUnit/firmware/specular_driver.c").string()), std::string::npos)
        << b.name << ": the driver did not come from the install prefix";
    for (const char* source : {"/examples/firmware_rv32/", "/firmware/src/", "/firmware/include/"})
      EXPECT_EQ(build.out.find(std::string(SPECULAR_SOURCE_DIR) + source), std::string::npos)
          << b.name << ": the build used the source tree's " << source;
  }
}

}  // namespace
