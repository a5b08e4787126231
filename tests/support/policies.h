// Every combination of the spec's two policies (Decisions: normalisation of ROM 38 ×
// second-pass result), as one GoogleTest parameter set with readable test names,
// e.g. `Policies/Exhaustive.Bounds/energy_literal`.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <tuple>

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

}  // namespace testing_support
}  // namespace specular
