#include "map_json.h"

#include <nlohmann/json.hpp>

#include "register_roles.h"
#include "specular/tlm/register_fields.h"
#include "specular/tlm/register_map.h"

namespace specular {
namespace ip_export {
namespace {

/// The enumerator's own name (to_string(Access) gives the docs' short forms).
const char* access_name(Access access) {
  switch (access) {
    case Access::read_only: return "read_only";
    case Access::read_write: return "read_write";
    case Access::write_1_to_clear: return "write_1_to_clear";
    case Access::self_clearing: return "self_clearing";
  }
  return "?";
}

}  // namespace

std::string register_map_json() {
  nlohmann::ordered_json map;
  map["map_size"] = map_size;
  map["registers"] = nlohmann::ordered_json::array();
  for (const RegisterInfo& row : register_map) {
    nlohmann::ordered_json r;
    r["name"] = row.name;
    r["offset"] = row.offset;
    r["words"] = row.words;
    r["access"] = access_name(row.access);
    r["description"] = row.description;
    nlohmann::ordered_json resets = nlohmann::ordered_json::array();
    for (std::uint32_t w = 0; w < row.words; ++w) resets.push_back(reset_of_word(row, w));
    r["reset_of_word"] = resets;
    if (row.reg == Reg::operands || row.reg == Reg::results) {
      nlohmann::ordered_json aliases = nlohmann::ordered_json::array();
      for (std::uint32_t w = 0; w < row.words; ++w)
        aliases.push_back(info(row.reg == Reg::operands ? operand_register(w) : result_register(w)).name);
      r["aliases"] = aliases;
    }
    nlohmann::ordered_json fields = nlohmann::ordered_json::array();
    for (const FieldInfo& f : fields_of(row.reg)) {
      nlohmann::ordered_json field;
      field["name"] = f.name;
      field["shift"] = f.shift;
      field["width"] = f.width;
      field["access"] = access_name(f.access);
      // who writes it besides software (register_roles.h): nothing for the constants
      const RowRole role = role_of(row.reg);
      field["hardware_writes"] = role != RowRole::constant && role != RowRole::configured;
      field["volatile"] = is_volatile(row.reg);
      nlohmann::ordered_json values = nlohmann::ordered_json::array();
      for (const FieldValue& v : field_values(f.values))
        values.push_back({{"value", v.value}, {"name", v.name}});
      field["values"] = values;
      fields.push_back(field);
    }
    r["fields"] = fields;
    map["registers"].push_back(r);
  }
  return map.dump(1) + "\n";
}

}  // namespace ip_export
}  // namespace specular
