// Strict conversions from command-line and CSV text to numbers.
//
// strtol/strtod accept "12abc" as 12 and " 1" as 1; a testbench that silently
// reads a different value than the user typed is worse than one that refuses, so
// every conversion here consumes the whole text or throws UsageError.
#pragma once

#include <cstdint>
#include <string>

namespace specular {
namespace tb {

/// A decimal integer (optional sign), the whole text. `what` names the value in
/// the message, `range` is the allowed range as the message should show it.
long long parse_integer(const std::string& text, const std::string& what,
                        const std::string& range);
/// An unsigned 64-bit decimal integer (for seeds).
std::uint64_t parse_unsigned64(const std::string& text, const std::string& what);
/// A real number (strtod syntax), the whole text; NaN and infinities are returned
/// as such so that the range check names them.
double parse_real(const std::string& text, const std::string& what, const std::string& range);
/// cos λ: a real number in [0, 1]; the message quotes the text as the user wrote it
/// ("cos = -0.1 is outside …", not the double's 17 digits). NaN and ±inf are refused.
double parse_cos(const std::string& text);

/// Smallest and largest clock period, in picoseconds: a multiple of 4 ps because the
/// pin harness changes inputs a quarter period before the clock edge; at most 1 ms so
/// that a million-operation sweep stays within SystemC's 64-bit time.
constexpr std::uint64_t clock_period_min_ps = 4;
constexpr std::uint64_t clock_period_max_ps = 1000000000;  // 1 ms
/// "10ns", "2.5 ns", "10000ps", "1us": a decimal number and a unit (fs, ps, ns, us,
/// ms, s), converted exactly to picoseconds; must be a positive multiple of 4 ps.
std::uint64_t parse_clock_period_ps(const std::string& text);

/// Leading and trailing blanks (spaces, tabs, CR) removed.
std::string trim(const std::string& text);

}  // namespace tb
}  // namespace specular
