// The JSON report of specular_tb (--format json) and the JSON pieces the partial
// results of sharded runs share with it (partial.h), written with nlohmann-json.
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

/// The --format json writer: {"tool", "settings", "results": [one object per
/// computation], "summary"}, results streamed as they come.
std::unique_ptr<Report> make_json_report(std::ostream& out);

}  // namespace tb
}  // namespace specular
