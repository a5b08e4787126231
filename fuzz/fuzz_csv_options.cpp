// libFuzzer target: specular_tb's text parsing — CSV stimulus files, the command line,
// the value parsers. Every input must end in a result or a UsageError (the user's
// error); anything else — another exception, a crash, undefined behaviour, a value
// accepted outside its documented range — is a finding.
//
// The input is used three ways: as a CSV file; split at newlines into argv; and each
// line through the single-value parsers.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "input.h"
#include "options.h"
#include "parse_values.h"
#include "specular/format.h"
#include "usage_error.h"

// libsystemc refers to sc_main; libFuzzer's main() runs instead, so it is never called.
extern "C" int sc_main(int, char**) { return 0; }

namespace {

using namespace specular;
using namespace specular::tb;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_csv_options: %s\n", what.c_str());
  std::abort();
}

const Formats& formats() {
  static const Formats f{Widths{}};
  return f;
}

void check_stimulus(const Stimulus& s) {
  const Formats& f = formats();
  if (!(s.cos >= 0.0 && s.cos <= 1.0)) finding("cos accepted outside [0, 1]: " + std::to_string(s.cos));
  if (s.operands.cos < 0 || s.operands.cos > f.cos.one()) finding("cos code outside [0, 1.0]");
  if (s.n < n_min || s.n > n_max || s.operands.n != static_cast<code_t>(s.n))
    finding("n accepted outside [1, 1000]: " + std::to_string(s.n));
  for (int ch = 0; ch < 3; ++ch)
    if (s.rgb[ch] > f.rgb.max_code() || s.operands.rgb[ch] != static_cast<code_t>(s.rgb[ch]))
      finding("intensity accepted outside [0, 255]: " + std::to_string(s.rgb[ch]));
  // Register 1 holds the nearest code (half a step at most away).
  if (std::fabs(f.cos.to_real(s.operands.cos) - s.cos) > f.cos.lsb() / 2 * (1 + 1e-12))
    finding("cos quantised to a code that is not the nearest");
}

void fuzz_csv(const std::string& text) {
  std::istringstream in(text);
  try {
    for (const Stimulus& s : read_stimuli(in, "fuzz.csv", formats())) check_stimulus(s);
  } catch (const UsageError&) {
  }
}

void fuzz_options(const std::string& text) {
  std::vector<std::string> args;
  std::string arg;
  std::istringstream in(text);
  while (std::getline(in, arg)) args.push_back(arg);
  Options o;
  try {
    o = parse_options(args);
  } catch (const UsageError&) {
    return;
  }
  if (o.help) return;
  if (o.stimulus == StimulusKind::point) {
    if (!(o.cos >= 0.0 && o.cos <= 1.0)) finding("--cos accepted outside [0, 1]");
    if (o.n < n_min || o.n > n_max) finding("--n accepted outside [1, 1000]");
  }
  for (long long v : o.rgb)
    if (v < 0 || v > formats().rgb.max_code()) finding("--rgb accepted outside [0, 255]");
  if (o.stimulus == StimulusKind::random && (o.random_count < 1 || o.random_count > random_count_max))
    finding("--random count outside its range");
  if (o.stimulus == StimulusKind::input && o.input_path.empty()) finding("empty --input accepted");
  if (o.clock_period_ps < clock_period_min_ps || o.clock_period_ps > clock_period_max_ps ||
      o.clock_period_ps % 4 != 0)
    finding("--clock-period accepted outside [4 ps, 1 ms] or not a multiple of 4 ps");
}

void fuzz_values(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    try {
      const std::uint64_t ps = parse_clock_period_ps(line);
      if (ps < clock_period_min_ps || ps > clock_period_max_ps || ps % 4 != 0)
        finding("parse_clock_period_ps returned " + std::to_string(ps));
    } catch (const UsageError&) {
    }
    try {
      parse_integer(line, "n", "[1, 1000]");
    } catch (const UsageError&) {
    }
    try {
      parse_unsigned64(line, "seed");
    } catch (const UsageError&) {
    }
    try {
      parse_real(line, "cos", "[0, 1]");
    } catch (const UsageError&) {
    }
    try {
      for (long long v : parse_rgb_triplet(line, formats(), "--rgb"))
        (void)v;  // range is checked by make_stimulus, fuzzed through the CSV path
    } catch (const UsageError&) {
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 8192) return -1;  // longer inputs add nothing but time
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz_csv(text);
  fuzz_options(text);
  fuzz_values(text);
  return 0;
}
