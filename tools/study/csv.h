// A small CSV writer: one header line, then rows of numbers (and an occasional
// label). Doubles are written with 10 significant digits, enough for errors of 1e-7
// on values of order 1 and for every integral the study reports.
#pragma once

#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

namespace specular {
namespace study {

class CsvWriter {
 public:
  /// Opens (truncates) `path` and writes the header; throws std::runtime_error
  /// naming the path if it cannot be written.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns);

  CsvWriter& cell(double value);
  CsvWriter& cell(long long value);
  CsvWriter& cell(const std::string& text);
  /// Ends the row; throws std::logic_error if it does not have one cell per column.
  void end_row();

  const std::string& path() const { return path_; }

 private:
  void separator();

  std::string path_;
  std::ofstream file_;
  std::size_t columns_;
  std::size_t cells_ = 0;
};

/// Creates `dir` (and its parents) if needed; throws std::runtime_error naming it.
void make_directory(const std::string& dir);

}  // namespace study
}  // namespace specular
