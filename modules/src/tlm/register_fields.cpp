#include "specular/tlm/register_fields.h"

#include <cctype>

#include "specular/format.h"

namespace specular {

namespace {
/// "device-energy" → "DEVICE_ENERGY": a C identifier's spelling of a policy's name.
std::string identifier(const char* name) {
  std::string id;
  for (const char* c = name; *c != '\0'; ++c)
    id += std::isalnum(static_cast<unsigned char>(*c))
              ? static_cast<char>(std::toupper(static_cast<unsigned char>(*c)))
              : '_';
  return id;
}

/// A policy's value: its name says all (no description).
template <typename Enum>
FieldValue policy_value(std::uint32_t code) {
  return {identifier(to_string(static_cast<Enum>(code))), code, ""};
}
}  // namespace

std::vector<FieldInfo> fields_of(Reg reg) {
  std::vector<FieldInfo> fields;
  for (const FieldInfo& f : register_fields)
    if (f.reg == reg) fields.push_back(f);
  if (fields.empty()) {
    const RegisterInfo& row = info(reg);
    fields.push_back({reg, "VALUE", 0, 32, row.access, FieldValues::none, row.description});
  }
  return fields;
}

std::vector<FieldValue> field_values(FieldValues values) {
  std::vector<FieldValue> list;
  for (std::uint32_t code = 0; code < value_count(values); ++code) {
    switch (values) {
      case FieldValues::none: break;
      case FieldValues::error_cause: {
        const ErrorCause cause = static_cast<ErrorCause>(code);
        list.push_back({identifier(to_string(cause)), code, describe(cause)});
        break;
      }
      case FieldValues::normalisation: list.push_back(policy_value<Normalisation>(code)); break;
      case FieldValues::saturation: list.push_back(policy_value<Saturation>(code)); break;
      case FieldValues::constants: list.push_back(policy_value<Constants>(code)); break;
    }
  }
  return list;
}

}  // namespace specular
