// Report writers: a readable text table, CSV and JSON, written as results stream in
// (a million-row sweep never sits in memory).
#pragma once

#include <cstdint>
#include <memory>
#include <ostream>
#include <string>

#include "scoreboard.h"

namespace specular {
namespace tb {

enum class OutputFormat { text, csv, json, jsonl };
const char* to_string(OutputFormat format);
/// "text", "csv", "json" or "jsonl"; throws UsageError naming the value and the choices.
OutputFormat parse_output_format(const std::string& text);

/// What the run was, for the report's header.
struct RunDescription {
  std::string model;              ///< "pin" or "core"
  std::string stimulus;           ///< "point", "input FILE", "sweep", "random N seed S"
  Config config{};
  std::uint64_t clock_period_ps = 0;
  std::size_t operations = 0;     ///< how many computations will follow
  bool text_rows = true;          ///< text format: one table row per computation
};

/// A code as the bus carries it: `width` bits in hex, two's complement for negative
/// codes, zero-padded to ceil(width/4) digits, e.g. hex_code(-1, 37) = "0x1fffffffff".
std::string hex_code(code_t code, int width);

/// The CSV header: every field of a computation, in the order rows carry them.
const char* csv_header();

class Report {
 public:
  virtual ~Report() = default;
  virtual void begin(const RunDescription& run) = 0;
  virtual void row(const Comparison& c) = 0;
  /// Hands the rows so far to the stream and flushes it (after each batch: a reader
  /// of a pipe sees them as they come, and a write error shows at once).
  virtual void flush() {}
  /// `seconds`: wall time of the run (text only: CSV and JSON stay reproducible).
  virtual void end(const Summary& summary, double seconds) = 0;
};

/// The writer for `format` on `out`. CSV carries only rows (pure CSV); its summary
/// goes to `side` (standard error). Text and JSON carry the summary themselves.
std::unique_ptr<Report> make_report(OutputFormat format, std::ostream& out, std::ostream& side);

/// Writes the summary as readable text (used by the text and CSV reports).
void write_summary_text(std::ostream& out, const Summary& summary, const RunDescription& run,
                        double seconds);

}  // namespace tb
}  // namespace specular
