// The variants' registry: one line per variant (name, factory), the patent's first.
#include "specular/variants/variant.h"

#include <functional>
#include <stdexcept>
#include <utility>

#include "specular/variants/exp2.h"
#include "specular/variants/one_pass.h"
#include "specular/variants/schlick.h"
#include "specular/variants/schlick_divider.h"
#include "specular/variants/us5739820.h"
#include "specular/variants/us5739820_pipelined.h"

namespace specular {
namespace variants {
namespace {

using Factory = std::function<std::unique_ptr<Variant>(const Config&)>;

const std::vector<std::pair<std::string, Factory>>& registry() {
  static const std::vector<std::pair<std::string, Factory>> table = {
      {"patent", [](const Config& c) { return std::make_unique<PatentDevice>(c); }},
      // Issue 26's variants register here, one line each.
      {"one_pass", [](const Config& c) { return std::make_unique<OnePass>(c, false); }},
      {"one_pass_pipelined", [](const Config& c) { return std::make_unique<OnePass>(c, true); }},
      {"exp2", [](const Config& c) { return std::make_unique<Exp2Variant>(c); }},
      {"us5739820", [](const Config& c) { return std::make_unique<Us5739820>(c); }},
      {"us5739820_pipelined", [](const Config& c) { return std::make_unique<Us5739820Pipelined>(c); }},
      {"schlick", [](const Config& c) { return std::make_unique<Schlick>(c); }},
      {"schlick_divider", [](const Config& c) { return std::make_unique<SchlickDivider>(c); }},
  };
  return table;
}

}  // namespace

std::vector<std::string> variant_names() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

std::unique_ptr<Variant> make_variant(std::string_view name, const Config& config) {
  for (const auto& entry : registry())
    if (entry.first == name) return entry.second(config);
  std::string known;
  for (const auto& entry : registry()) known += (known.empty() ? "" : ", ") + entry.first;
  throw std::invalid_argument("unknown variant '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace variants
}  // namespace specular
