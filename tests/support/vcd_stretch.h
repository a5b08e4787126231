// One stretch of a waveform against the same stretch of another (issue 27): a trace
// window (--trace-ops) against a whole-run VCD, a failing operation's replay
// (--trace-failures) against the run's own trace, times shifted by a constant.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "vcd.h"

namespace specular {
namespace testing_support {

/// The full name of the first variable called `name` (any scope).
inline std::string var_named(const Vcd& vcd, const std::string& name) {
  for (const Vcd::Var& v : vcd.vars)
    if (v.name == name) return v.full();
  ADD_FAILURE() << "no variable " << name;
  return "";
}

/// The earliest instant of a VCD: its initial values'.
inline long long first_time(const Vcd& vcd) {
  long long t = -1;
  for (const auto& [id, list] : vcd.changes)
    if (!list.empty() && (t < 0 || list.front().first < t)) t = list.front().first;
  return t;
}

/// Every variable of `part` holds, at `from` and at every instant of (from, to], the
/// values `whole` holds at that instant minus `shift`, and changes exactly where it
/// does. Returns how many value changes were compared (0 would prove nothing).
/// `only`: compare only the variables whose name begins so ("pin": the pins).
inline std::size_t expect_same_stretch(const Vcd& part, const Vcd& whole, long long shift,
                                       long long from, long long to, const std::string& only = "") {
  std::size_t compared = 0;
  for (const Vcd::Var& v : part.vars) {
    if (v.name.rfind(only, 0) != 0) continue;
    const std::string name = v.full();
    if (whole.find(name) == nullptr) {
      ADD_FAILURE() << name << " is not in the whole run's trace";
      continue;
    }
    EXPECT_EQ(part.at(name, from), whole.at(name, from - shift)) << name << " at " << from;
    std::vector<std::pair<long long, std::string>> mine, theirs;
    for (const auto& [t, value] : part.of(name))
      if (t > from && t <= to) mine.emplace_back(t, value);
    for (const auto& [t, value] : whole.of(name))
      if (t > from - shift && t <= to - shift) theirs.emplace_back(t + shift, value);
    EXPECT_EQ(mine, theirs) << name << " in (" << from << ", " << to << "]";
    compared += mine.size();
  }
  return compared;
}

}  // namespace testing_support
}  // namespace specular
