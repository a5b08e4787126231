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
  const Outcome configure = run_command(
      cmake() + " -S " + shell_quoted(consumer) + " -B " + shell_quoted(dir / "build") +
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

}  // namespace
