// SpecularUnit::core is kernel-free (issue 29): a plain int main() links it without
// libsystemc and computes Core's bits. Runs the project's build of
// examples/consumer/core_main.cpp (specular_core_example), which checks Core against
// the patent's formula in double within the documented bound; scripts/verify/consumer_check.sh
// does the same against the installed package.
#include <gtest/gtest.h>

#include <string>

#include "support/subprocess.h"

namespace {

const std::string binary_dir = SPECULAR_BINARY_DIR;

// Neither the core's archive nor the program needs anything of SystemC.
TEST(CoreKernelFree, TheCoreLibraryAndAPlainMainOnItNeedNoSystemC) {
  const auto dir = specular::testing_support::fresh_directory("run");
  const std::string archive = SPECULAR_CORE_LIBRARY;  // the archive, or the .so of a shared build
  auto outcome = specular::testing_support::run_command("nm -u -C '" + archive + "'", dir);
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("std::"), std::string::npos) << "nm listed the undefined symbols";
  EXPECT_EQ(outcome.out.find("sc_core::"), std::string::npos) << outcome.out;
  EXPECT_EQ(outcome.out.find("sc_dt::"), std::string::npos) << outcome.out;
  EXPECT_EQ(outcome.out.find("sc_main"), std::string::npos) << outcome.out;

  const std::string exe = binary_dir + "/examples/specular_core_example";
  outcome = specular::testing_support::run_command("readelf -d '" + exe + "'", dir);
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("(NEEDED)"), std::string::npos) << outcome.out;
  EXPECT_EQ(outcome.out.find("libsystemc"), std::string::npos) << outcome.out;
}

// 10 cos codes x 6 exponents x 3 colours x 3 channels, each within the bound.
TEST(CoreKernelFree, APlainMainComputesCoresBitsWithinTheFormulasBound) {
  const auto dir = specular::testing_support::fresh_directory("run");
  const auto outcome =
      specular::testing_support::run_command("'" + binary_dir + "/examples/specular_core_example'", dir);
  EXPECT_EQ(outcome.status, 0) << outcome.out << outcome.err;
  EXPECT_NE(outcome.out.find("consumer_core: 540/540 outputs of Core within the documented bound "
                             "of the double formula: PASS"),
            std::string::npos)
      << outcome.out;
}

}  // namespace
