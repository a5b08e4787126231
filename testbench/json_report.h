// The JSON objects specular_tb's report (--format json and jsonl: settings, summary)
// and the partial results of sharded runs (partial.h) share, written and read with
// nlohmann-json. The report's rows stay on issue 27's buffered writer (report.cpp).
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "json.h"
#include "report.h"
#include "scoreboard.h"

namespace specular {
namespace tb {

/// What names a run: model, stimulus, policies, clock and operation count — the first
/// fields of the report's settings and of a partial result's (partial.h).
Json run_settings_json(const RunDescription& run);
/// The report's "settings" object: run_settings_json and the formats.
Json settings_json(const RunDescription& run);
/// The report's "summary" object. `places` adds what a merge needs and a report does
/// not show: each maximum's operation index ("at") and the results' checksum.
Json summary_json(const Summary& summary, bool places = false);
/// The inverse of summary_json(summary, true); throws std::exception (nlohmann's
/// type or out-of-range errors) on a malformed object.
Summary summary_from_json(const Json& json);

}  // namespace tb
}  // namespace specular
