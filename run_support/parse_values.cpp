#include "parse_values.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "usage_error.h"

namespace specular {
namespace tb {

std::string trim(const std::string& text) {
  const char* blanks = " \t\r\n";
  const auto first = text.find_first_not_of(blanks);
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(blanks);
  return text.substr(first, last - first + 1);
}

namespace {
bool is_digits(const std::string& text, std::size_t from) {
  if (from >= text.size()) return false;
  for (std::size_t i = from; i < text.size(); ++i)
    if (text[i] < '0' || text[i] > '9') return false;
  return true;
}
}  // namespace

long long parse_integer(const std::string& text, const std::string& what,
                        const std::string& range) {
  const std::size_t digits_from = (!text.empty() && (text[0] == '-' || text[0] == '+')) ? 1 : 0;
  if (!is_digits(text, digits_from))
    throw UsageError(what + " = '" + text + "' is not an integer; allowed range " + range);
  errno = 0;
  const long long value = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE)
    throw UsageError(what + " = " + text + " is outside the allowed range " + range);
  return value;
}

std::uint64_t parse_unsigned64(const std::string& text, const std::string& what) {
  const std::string range = "[0, " + std::to_string(std::numeric_limits<std::uint64_t>::max()) + "]";
  if (!is_digits(text, 0))
    throw UsageError(what + " = '" + text + "' is not an unsigned integer; allowed range " + range);
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE)
    throw UsageError(what + " = " + text + " is outside the allowed range " + range);
  return value;
}

double parse_real(const std::string& text, const std::string& what, const std::string& range) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const bool blank_start = text.empty() || text[0] == ' ' || text[0] == '\t';
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (blank_start || end == begin || *end != '\0')
    throw UsageError(what + " = '" + text + "' is not a number; allowed range " + range);
  // Overflow gives ±HUGE_VAL (out of any range, caught by the caller's check);
  // underflow gives a tiny or zero value, which is what the user wrote, near enough.
  return value;
}

double parse_cos(const std::string& text) {
  const double value = parse_real(text, "cos", "[0, 1]");
  if (!(value >= 0.0 && value <= 1.0))  // NaN fails both comparisons
    throw UsageError("cos = " + text + " is outside the allowed range [0, 1]");
  return value;
}

std::uint64_t parse_clock_period_ps(const std::string& raw) {
  const std::string text = trim(raw);
  const std::string range = "[4 ps, 1 ms], a multiple of 4 ps (e.g. 10ns)";
  auto bad = [&](const std::string& why) {
    return UsageError("--clock-period = '" + raw + "' " + why + "; allowed range " + range);
  };
  // Split "<digits>[.<digits>]" from the unit.
  std::size_t i = 0;
  std::uint64_t mantissa = 0;
  int fraction_digits = 0;
  bool any_digit = false, in_fraction = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '.' && !in_fraction) { in_fraction = true; continue; }
    if (c < '0' || c > '9') break;
    any_digit = true;
    if (mantissa > (std::numeric_limits<std::uint64_t>::max() - 9) / 10) throw bad("is too large");
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
    if (in_fraction) ++fraction_digits;
  }
  if (!any_digit) throw bad("is not a time");
  const std::string unit = trim(text.substr(i));
  int unit_exponent = 0;  // the unit in powers of ten of a picosecond
  if (unit == "fs") unit_exponent = -3;
  else if (unit == "ps") unit_exponent = 0;
  else if (unit == "ns") unit_exponent = 3;
  else if (unit == "us") unit_exponent = 6;
  else if (unit == "ms") unit_exponent = 9;
  else if (unit == "s") unit_exponent = 12;
  else if (unit.empty()) throw bad("has no unit (fs, ps, ns, us, ms, s)");
  else throw bad("has an unknown unit '" + unit + "' (fs, ps, ns, us, ms, s)");

  int exponent = unit_exponent - fraction_digits;
  std::uint64_t ps = mantissa;
  for (; exponent < 0; ++exponent) {
    if (ps % 10 != 0) throw bad("is not a whole number of picoseconds");
    ps /= 10;
  }
  for (; exponent > 0; --exponent) {
    if (ps > clock_period_max_ps) throw bad("is too long");
    ps *= 10;
  }
  if (ps < clock_period_min_ps || ps > clock_period_max_ps) throw bad("is out of range");
  if (ps % 4 != 0) throw bad("is not a multiple of 4 ps");
  return ps;
}

}  // namespace tb
}  // namespace specular
