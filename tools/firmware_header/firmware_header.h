// The firmware C header (firmware/include/specular/specular_regs.h), printed from the
// register map (register_map.h) and its field table (register_fields.h): the offsets,
// access and reset values, fields and their values, window sizes and interrupt rules a
// C driver needs, as plain C99 macros. specular_firmware_header writes or checks it.
#pragma once

#include <string>

namespace specular {
namespace firmware_header {

/// Where the header lives, relative to the source tree.
constexpr const char* path = "firmware/include/specular/specular_regs.h";

/// The whole header's text.
std::string text();

}  // namespace firmware_header
}  // namespace specular
