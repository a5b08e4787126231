// Every combination of the spec's two policies (Decisions: normalisation of ROM 38 ×
// second-pass result), as one GoogleTest parameter set with readable test names,
// e.g. `Policies/Exhaustive.Bounds/energy_literal`.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "specular/core.h"
#include "specular/format.h"

namespace specular {
namespace testing_support {

using PolicyPair = std::tuple<Normalisation, Saturation>;

/// For a fixture derived from ::testing::TestWithParam<PolicyPair>.
class PolicyTest : public ::testing::TestWithParam<PolicyPair> {};

/// patent, energy, none × clamp, literal: the six devices a user can build.
inline auto every_policy() {
  return ::testing::Combine(
      ::testing::Values(Normalisation::patent, Normalisation::energy, Normalisation::none),
      ::testing::Values(Saturation::clamp, Saturation::literal));
}

inline std::string policy_name(const ::testing::TestParamInfo<PolicyPair>& info) {
  return std::string(to_string(std::get<0>(info.param))) + "_" +
         to_string(std::get<1>(info.param));
}

/// Every device a user can configure: normalisation × saturation × constants (the
/// constants policy of issue 14 too), 24 combinations; a few are refused when built
/// (Rom38Table says why), and tests over them check that the refusal holds.
using DevicePolicy = std::tuple<Normalisation, Saturation, Constants>;
class DevicePolicyTest : public ::testing::TestWithParam<DevicePolicy> {
 protected:
  Config config() const {
    Config c;
    c.normalisation = std::get<0>(GetParam());
    c.saturation = std::get<1>(GetParam());
    c.constants = std::get<2>(GetParam());
    return c;
  }
};

inline auto every_device() {
  return ::testing::Combine(
      ::testing::Values(Normalisation::patent, Normalisation::energy, Normalisation::none,
                        Normalisation::device_energy),
      ::testing::Values(Saturation::clamp, Saturation::literal),
      ::testing::Values(Constants::patent, Constants::minimax_half, Constants::minimax));
}

inline std::string device_name(const ::testing::TestParamInfo<DevicePolicy>& info) {
  std::string name = std::string(to_string(std::get<0>(info.param))) + "_" +
                     to_string(std::get<1>(info.param)) + "_" + to_string(std::get<2>(info.param));
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

}  // namespace testing_support
}  // namespace specular
