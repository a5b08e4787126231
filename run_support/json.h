// The JSON of every long run's files (reports, partial results): nlohmann-json with the
// keys in the order they are written, so a file reads top to bottom.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace specular {
namespace tb {

/// Keys keep the order they are written in (the report reads top to bottom).
using Json = nlohmann::ordered_json;

/// One line of JSON; bytes that are not UTF-8 (a file name) become U+FFFD.
std::string dump_json(const Json& json);

}  // namespace tb
}  // namespace specular
