// Output files that never look complete unless they are: everything is written to a
// temporary file beside the target and renamed over it only when the run finished.
#pragma once

#include <fstream>
#include <string>

namespace specular {
namespace tb {

class AtomicFile {
 public:
  /// Creates the temporary file `<dir>/.<name>.tmp-XXXXXX<suffix>` next to `path`,
  /// which proves early that the target directory can be written. Throws UsageError
  /// (naming `option` and the path) when it cannot, or when `path` is a directory.
  AtomicFile(const std::string& path, const std::string& option, const std::string& suffix = "");
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }
  /// Renames the temporary file to `path`. Throws UsageError if that fails.
  void commit();

 private:
  std::string path_;
  std::string option_;
  std::string temp_path_;
  bool committed_ = false;
};

/// An AtomicFile written through a stream (the report).
class AtomicOutputStream {
 public:
  AtomicOutputStream(const std::string& path, const std::string& option);
  std::ostream& stream() { return stream_; }
  /// Flushes and closes the stream, checks nothing failed (a full disk), renames.
  void commit();

 private:
  AtomicFile file_;
  std::string option_;
  std::ofstream stream_;
};

}  // namespace tb
}  // namespace specular
