// specular_soak --constants: every stage (core, pin, TLM lt, TLM pin) runs the device
// under the constants policy and checks it against the double reference and the core
// under the same policy; the TLM target's CONFIG shows the policy (bits 6:5, written
// out here by hand), a fault is still caught, and a bad name is refused.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "support/soak_run.h"

namespace {

using specular::testing_support::run_soak;
using specular::testing_support::SoakRun;

const std::map<std::string, double> planned = {
    {"core", 20000}, {"pin", 2000}, {"tlm", 2000}, {"tlm-pin", 200}};
const std::string counts = "--core 20000 --pin 2000 --tlm 2000 --tlm-pin 200";

// CONFIG at the default widths (RGB 8 bits, OUT 13 fraction bits, COS 16), patent
// normalisation, clamp: 0x080D1000; the constants in bits 6:5.
constexpr double config_default = 0x080D1000;

TEST(SoakConstants, EveryStagePassesUnderEachConstantsPolicy) {
  for (const auto& [name, code] : std::map<std::string, int>{{"minimax-half", 1}, {"minimax", 2}}) {
    SCOPED_TRACE(name);
    const SoakRun r = run_soak(counts + " --constants " + name);
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("; constants " + name + "\n"), std::string::npos) << r.out;
    ASSERT_EQ(r.stages.size(), planned.size()) << r.out;
    for (const auto& [stage, ops] : planned) {
      SCOPED_TRACE(stage);
      EXPECT_EQ(r.stages.at(stage).at("ops"), ops);
      EXPECT_EQ(r.stages.at(stage).at("mismatches"), 0);
    }
    for (const char* stage : {"tlm", "tlm-pin"})
      EXPECT_EQ(r.stages.at(stage).at("config"), config_default + code * 32) << stage;
  }
  const SoakRun patent = run_soak(counts);
  EXPECT_EQ(patent.status, 0) << patent.out;
  EXPECT_EQ(patent.stages.at("tlm").at("config"), config_default) << "patent constants: 0";
}

TEST(SoakConstants, AnInjectedFaultIsCaughtUnderTheConstants) {
  const SoakRun r = run_soak(counts + " --constants minimax --inject-fault 7");
  EXPECT_EQ(r.status, 1) << r.out;
  for (const auto& [stage, ops] : planned) EXPECT_GE(r.stages.at(stage).at("mismatches"), 1) << stage;
}

TEST(SoakConstants, BadConstantsExitTwoNamingTheChoices) {
  const SoakRun r = run_soak("--core 10 --pin 0 --tlm 0 --tlm-pin 0 --constants schlick");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--constants: constants policy 'schlick' is not one of: patent, minimax-half, minimax"),
            std::string::npos)
      << r.out;
}

}  // namespace

// Issue 35: the TLM pin target's delay policy is a setting, chosen with --pin-delay
// (default keep); both policies give the core's bits, a bad name is refused naming the
// allowed ones.
namespace {

TEST(SoakPinDelay, EitherPolicyGivesTheCoresBitsAndABadOneIsNamed) {
  for (const std::string policy : {"keep", "consume"}) {
    SCOPED_TRACE(policy);
    const SoakRun r = run_soak("--core 0 --pin 0 --tlm 0 --tlm-pin 40 --pin-delay " + policy);
    EXPECT_EQ(r.status, 0) << r.out;
    ASSERT_EQ(r.stages.count("tlm-pin"), 1u) << r.out;
    EXPECT_EQ(r.stages.at("tlm-pin").at("ops"), 40);
    EXPECT_EQ(r.stages.at("tlm-pin").at("mismatches"), 0);
  }
  const SoakRun bad = run_soak("--core 0 --pin 0 --tlm 0 --tlm-pin 1 --pin-delay later");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("--pin-delay: pin delay policy 'later' is not one of: keep, consume"),
            std::string::npos)
      << bad.out;
}

}  // namespace
