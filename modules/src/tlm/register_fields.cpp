#include "specular/tlm/register_fields.h"

#include <cctype>

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

template <typename Enum>
FieldValue value_of(Enum value, std::string description = "") {
  return {identifier(to_string(value)), static_cast<std::uint32_t>(value), std::move(description)};
}
}  // namespace

std::vector<FieldValue> field_values(FieldValues values) {
  std::vector<FieldValue> list;
  switch (values) {
    case FieldValues::none: break;
    case FieldValues::error_cause:
      for (std::uint8_t c = 0; c < error_cause_count; ++c)
        list.push_back(value_of(static_cast<ErrorCause>(c), describe(static_cast<ErrorCause>(c))));
      break;
    case FieldValues::normalisation:
      for (Normalisation policy : every_normalisation) list.push_back(value_of(policy));
      break;
    case FieldValues::saturation:
      for (Saturation policy : {Saturation::clamp, Saturation::literal})
        list.push_back(value_of(policy));
      break;
    case FieldValues::constants:
      for (Constants policy : every_constants) list.push_back(value_of(policy));
      break;
  }
  return list;
}

}  // namespace specular
