#include "csv.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace specular {
namespace study {

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), file_(path), columns_(columns.size()) {
  if (!file_) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  for (const std::string& column : columns) cell(column);
  end_row();
}

void CsvWriter::separator() {
  if (cells_++ > 0) file_ << ',';
}

CsvWriter& CsvWriter::cell(double value) {
  separator();
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  file_ << text;
  return *this;
}

CsvWriter& CsvWriter::cell(long long value) {
  separator();
  file_ << value;
  return *this;
}

CsvWriter& CsvWriter::cell(const std::string& text) {
  separator();
  file_ << text;
  return *this;
}

void CsvWriter::end_row() {
  if (cells_ != columns_)
    throw std::logic_error(path_ + ": a row has " + std::to_string(cells_) + " cells, the header " +
                           std::to_string(columns_));
  file_ << '\n';
  cells_ = 0;
  if (!file_) throw std::runtime_error("writing '" + path_ + "' failed");
}

void make_directory(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir))
    throw std::runtime_error("cannot create directory '" + dir + "'" +
                             (error ? ": " + error.message() : std::string()));
}

}  // namespace study
}  // namespace specular
