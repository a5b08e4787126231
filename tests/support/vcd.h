// A VCD file as GTKWave reads it, for the waveform tests (test_vcd_waveform.cpp: the
// SystemC model's trace; test_rtl_vcd.cpp: Verilator's traces of the RTL twins).
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace specular {
namespace testing_support {

/// A VCD as GTKWave reads it: variables by full dotted name, value changes by id.
struct Vcd {
  struct Var {
    std::string type;   ///< wire / real
    int width = 0;
    std::string id;
    std::string scope;  ///< "SystemC.tb.dut"
    std::string name;   ///< "reg9_q"
    std::string range;  ///< "[36:0]" or ""
    std::string full() const { return scope + "." + name; }
    std::string gtkwave() const { return full() + range; }  ///< how a .gtkw names it
  };
  double timescale_seconds = 0;
  std::vector<Var> vars;
  std::set<std::string> scopes;
  /// id → (time in timescale units, value text: "0", "1", "b101", "r0.25")
  std::map<std::string, std::vector<std::pair<long long, std::string>>> changes;

  const Var* find(const std::string& full_name) const {
    for (const Var& v : vars)
      if (v.full() == full_name) return &v;
    return nullptr;
  }
  const std::vector<std::pair<long long, std::string>>& of(const std::string& full_name) const {
    static const std::vector<std::pair<long long, std::string>> none;
    const Var* v = find(full_name);
    if (v == nullptr) return none;
    const auto it = changes.find(v->id);
    return it == changes.end() ? none : it->second;
  }
  /// The value of a variable just after time t (the last change at or before t).
  std::string at(const std::string& full_name, long long t) const {
    std::string value;
    for (const auto& [when, v] : of(full_name))
      if (when <= t) value = v;
    return value;
  }
  /// Times at which a 1-bit variable rises.
  std::vector<long long> rises(const std::string& full_name) const {
    std::vector<long long> times;
    std::string previous = "x";
    for (const auto& [when, v] : of(full_name)) {
      if (v == "1" && previous != "1" && previous != "x") times.push_back(when);
      previous = v;
    }
    return times;
  }
};

inline Vcd parse_vcd(const std::string& text) {
  Vcd vcd;
  std::istringstream in(text);
  std::vector<std::string> scope;
  std::string word;
  long long now = 0;
  bool definitions = true;
  auto joined = [&scope] {
    std::string s;
    for (const auto& part : scope) s += (s.empty() ? "" : ".") + part;
    return s;
  };
  while (in >> word) {
    if (definitions) {
      if (word == "$timescale") {
        std::string number, unit, end;
        in >> number;
        // "1 ps" or "1ps"
        std::size_t digits = 0;
        while (digits < number.size() && std::isdigit(static_cast<unsigned char>(number[digits]))) ++digits;
        unit = number.substr(digits);
        number = number.substr(0, digits);
        if (unit.empty()) in >> unit;
        const std::map<std::string, double> units = {{"s", 1},     {"ms", 1e-3},  {"us", 1e-6},
                                                     {"ns", 1e-9}, {"ps", 1e-12}, {"fs", 1e-15}};
        vcd.timescale_seconds = std::stod(number) * units.at(unit);
        in >> end;
      } else if (word == "$scope") {
        std::string kind, name, end;
        in >> kind >> name >> end;
        scope.push_back(name);
        vcd.scopes.insert(joined());
      } else if (word == "$upscope") {
        in >> word;
        scope.pop_back();
      } else if (word == "$var") {
        Vcd::Var v;
        in >> v.type >> v.width >> v.id >> v.name;
        std::string next;
        in >> next;
        if (next != "$end") {
          v.range = next;
          in >> next;
        }
        v.scope = joined();
        vcd.vars.push_back(v);
      } else if (word == "$enddefinitions") {
        in >> word;
        definitions = false;
      }
      continue;
    }
    if (word == "$comment") {
      while (in >> word && word != "$end") {
      }
    } else if (word[0] == '#') {
      now = std::stoll(word.substr(1));
    } else if (word[0] == '$') {
      continue;  // $dumpvars, $end, $comment … (the comment's words are skipped below)
    } else if (word[0] == 'b' || word[0] == 'r') {
      std::string id;
      in >> id;
      vcd.changes[id].emplace_back(now, word);
    } else if (word[0] == '0' || word[0] == '1' || word[0] == 'x' || word[0] == 'z') {
      vcd.changes[word.substr(1)].emplace_back(now, word.substr(0, 1));
    }
  }
  return vcd;
}

/// The integer code of a bus at time t, sign-extended when its format is signed.
inline long long code_at(const Vcd& vcd, const std::string& full_name, bool is_signed, long long t) {
  const Vcd::Var* v = vcd.find(full_name);
  EXPECT_NE(v, nullptr) << full_name;
  const std::string value = v == nullptr ? "" : vcd.at(full_name, t);
  EXPECT_FALSE(value.empty()) << full_name << " has no value at " << t;
  if (v == nullptr || value.size() < 2) return 0;
  // VCD drops leading zeros; a negative code keeps its leading one at full width.
  const std::string bits = value.substr(1);
  long long code = static_cast<long long>(std::stoull(bits, nullptr, 2));
  if (is_signed && static_cast<int>(bits.size()) == v->width && bits[0] == '1')
    code -= 1LL << v->width;
  return code;
}

}  // namespace testing_support
}  // namespace specular
