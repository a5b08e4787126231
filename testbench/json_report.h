// The JSON pieces of the partial results of sharded runs (partial.h), written and read
// with nlohmann-json: the settings and the summary, the latter with each maximum's
// place and the results' checksum. (specular_tb --format json keeps issue 27's
// buffered writer, report.cpp, which JSON Lines is built on; its summary object has
// the same keys as summary_json(summary, false).)
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "report.h"
#include "scoreboard.h"

namespace specular {
namespace tb {

/// Keys keep the order they are written in (the report reads top to bottom).
using Json = nlohmann::ordered_json;

/// One line of JSON; bytes that are not UTF-8 (a file name) become U+FFFD.
std::string dump_json(const Json& json);

/// The report's "settings" object.
Json settings_json(const RunDescription& run);
/// The report's "summary" object. `places` adds what a merge needs and a report does
/// not show: each maximum's operation index ("at") and the results' checksum.
Json summary_json(const Summary& summary, bool places = false);
/// The inverse of summary_json(summary, true); throws std::exception (nlohmann's
/// type or out-of-range errors) on a malformed object.
Summary summary_from_json(const Json& json);

}  // namespace tb
}  // namespace specular
