#include "progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <utility>

namespace specular {
namespace tb {

namespace {
std::string grouped(std::uint64_t value) {
  std::string digits = std::to_string(value), text;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
    text += digits[i];
  }
  return text;
}

std::string rate_text(double per_second) {
  char buffer[32];
  if (per_second >= 1e6) std::snprintf(buffer, sizeof buffer, "%.2f M/s", per_second / 1e6);
  else if (per_second >= 1e3) std::snprintf(buffer, sizeof buffer, "%.1f k/s", per_second / 1e3);
  else std::snprintf(buffer, sizeof buffer, "%.1f /s", per_second);
  return buffer;
}

std::string duration_text(double seconds) {
  const auto s = static_cast<long long>(std::llround(seconds));
  char buffer[32];
  if (s >= 3600) std::snprintf(buffer, sizeof buffer, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(buffer, sizeof buffer, "%lld:%02lld", s / 60, s % 60);
  return buffer;
}
}  // namespace

std::string progress_line(std::uint64_t done, std::uint64_t total, double seconds,
                          const std::string& unit, const std::string& label) {
  std::string line = "  " + (label.empty() ? std::string() : label + ": ") + grouped(done) + " / " +
                     grouped(total) + " " + unit;
  if (total > 0) {
    char percent[16];
    std::snprintf(percent, sizeof percent, " (%.1f%%)", 100.0 * static_cast<double>(done) / total);
    line += percent;
  }
  if (done > 0 && seconds > 0) {
    const double rate = static_cast<double>(done) / seconds;
    line += ", " + rate_text(rate);
    if (total >= done) line += ", " + duration_text(static_cast<double>(total - done) / rate) + " left";
  }
  return line;
}

Progress::Progress(std::ostream& out, std::uint64_t total, bool enabled, std::string unit,
                   std::string label)
    : out_(out), total_(total), enabled_(enabled), unit_(std::move(unit)), label_(std::move(label)),
      started_(std::chrono::steady_clock::now()), last_(started_) {}

void Progress::update(std::uint64_t done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(500)) return;
  last_ = now;
  const double seconds = std::chrono::duration<double>(now - started_).count();
  out_ << '\r' << progress_line(done, total_, seconds, unit_, label_) << "\033[K" << std::flush;
  drawn_ = true;
}

void Progress::finish() {
  if (drawn_) out_ << "\r\033[K" << std::flush;
  drawn_ = false;
}

bool progress_wanted(bool quiet) { return !quiet && isatty(STDERR_FILENO) == 1; }

}  // namespace tb
}  // namespace specular
