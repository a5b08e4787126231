// specular_progress DONE TOTAL SECONDS [UNIT [LABEL]]: prints progress_line() (progress.h)
// on standard output, for scripts whose long runs report progress the way specular_tb
// does (scripts/gatesim.sh; the script decides whether standard error is a terminal).
// Exit 2 with a message naming the bad value and the allowed range.
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

#include "progress.h"

namespace {
bool parse_count(const char* text, std::uint64_t& value) {
  if (*text < '0' || *text > '9') return false;
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text, &end, 10);
  if (errno != 0 || *end != '\0') return false;
  value = v;
  return true;
}
}  // namespace

int main(int argc, char** argv) {
  const char* usage = "usage: specular_progress DONE TOTAL SECONDS [UNIT [LABEL]]\n";
  if (argc < 4 || argc > 6) {
    std::cerr << "specular_progress: expected 3 to 5 arguments, got " << argc - 1 << "\n" << usage;
    return 2;
  }
  std::uint64_t done = 0, total = 0;
  if (!parse_count(argv[1], done)) {
    std::cerr << "specular_progress: DONE '" << argv[1] << "' is not a whole number from 0 to 2^64-1\n";
    return 2;
  }
  if (!parse_count(argv[2], total)) {
    std::cerr << "specular_progress: TOTAL '" << argv[2] << "' is not a whole number from 0 to 2^64-1\n";
    return 2;
  }
  char* end = nullptr;
  const double seconds = std::strtod(argv[3], &end);
  if (end == argv[3] || *end != '\0' || !(seconds >= 0 && seconds <= 1e9)) {
    std::cerr << "specular_progress: SECONDS '" << argv[3] << "' is not a time in seconds from 0 to 1e9\n";
    return 2;
  }
  std::cout << specular::tb::progress_line(done, total, seconds, argc > 4 ? argv[4] : "operations",
                                           argc > 5 ? argv[5] : "")
            << "\n";
  return 0;
}
