#include "output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "usage_error.h"

namespace specular {
namespace tb {

namespace fs = std::filesystem;

AtomicFile::AtomicFile(const std::string& path, const std::string& option,
                       const std::string& suffix)
    : path_(path), option_(option) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw UsageError(option + ": cannot write '" + path + "': it is a directory");
  // Only regular files are replaced by the rename: renaming over a device (/dev/null),
  // a FIFO or a symbolic link would replace that node itself (issue 5 finding: as
  // root, --output /dev/full turned /dev/full into a plain file). A link is followed
  // to the regular file it names.
  fs::path target(path);
  if (fs::is_symlink(fs::symlink_status(target, ec))) {
    target = fs::canonical(target, ec);
    if (ec)
      throw UsageError(option + ": cannot write '" + path + "': the link leads nowhere (" +
                       ec.message() + ")");
    path_ = target.string();
  }
  if (fs::exists(target, ec) && !fs::is_regular_file(target, ec))
    throw UsageError(option + ": cannot write '" + path +
                     "': not a regular file (a device, FIFO or socket); give a file name");
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string pattern =
      (directory / ("." + target.filename().string() + ".tmp-XXXXXX" + suffix)).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemps(name.data(), static_cast<int>(suffix.size()));
  if (fd < 0)
    throw UsageError(option + ": cannot write '" + path + "': " + std::strerror(errno));
  // mkstemps creates the file 0600; give it the permissions a plain open would.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  close(fd);
  temp_path_ = name.data();
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicFile::commit() {
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0)
    throw UsageError(option_ + ": cannot write '" + path_ + "': " + std::strerror(errno));
  committed_ = true;
}

AtomicOutputStream::AtomicOutputStream(const std::string& path, const std::string& option)
    : file_(path, option), option_(option), stream_(file_.temp_path(), std::ios::out | std::ios::trunc) {
  if (!stream_)
    throw UsageError(option + ": cannot write '" + path + "': " + std::strerror(errno));
}

void AtomicOutputStream::commit() {
  stream_.flush();
  stream_.close();
  if (stream_.fail())
    throw UsageError(option_ + ": cannot write '" + file_.path() + "' (disk full?)");
  file_.commit();
}

}  // namespace tb
}  // namespace specular
