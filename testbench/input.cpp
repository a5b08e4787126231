#include "input.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "parse_values.h"
#include "usage_error.h"

namespace specular {
namespace tb {

namespace {
std::string with_context(const std::string& context, const std::string& message) {
  return context.empty() ? message : context + ": " + message;
}

std::string rgb_range(const Formats& formats) {
  return "[0, " + std::to_string(formats.rgb.max_code()) + "]";
}
}  // namespace

Stimulus make_stimulus(const Formats& formats, double cos, long long n,
                       const std::array<long long, 3>& rgb, const std::string& context) {
  Stimulus s;
  try {
    s.operands.cos = quantise_cos(formats, cos);
    s.n = check_n(n);
    static const char* channels[3] = {"R", "G", "B"};
    for (int ch = 0; ch < 3; ++ch) s.rgb[ch] = check_rgb(formats, rgb[ch], channels[ch]);
  } catch (const std::exception& e) {  // the range checks of format.h
    throw UsageError(with_context(context, e.what()));
  }
  s.cos = cos;
  s.operands.n = s.n;
  for (int ch = 0; ch < 3; ++ch) s.operands.rgb[ch] = s.rgb[ch];
  return s;
}

namespace {
std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> fields;
  std::size_t from = 0;
  while (true) {
    const std::size_t at = text.find(separator, from);
    fields.push_back(trim(text.substr(from, at == std::string::npos ? std::string::npos : at - from)));
    if (at == std::string::npos) break;
    from = at + 1;
  }
  return fields;
}
}  // namespace

std::array<long long, 3> parse_rgb_triplet(const std::string& text, const Formats& formats,
                                           const std::string& context) {
  const std::string range = rgb_range(formats);
  const std::vector<std::string> fields = split(text, ',');
  if (fields.size() != 3)
    throw UsageError(with_context(context, "'" + text + "' has " + std::to_string(fields.size()) +
                                               " value(s); expected 3 (R,G,B), each in " + range));
  static const char* channels[3] = {"R", "G", "B"};
  std::array<long long, 3> rgb{};
  for (int ch = 0; ch < 3; ++ch) {
    try {
      rgb[ch] = parse_integer(fields[ch], channels[ch], range);
    } catch (const UsageError& e) {
      throw UsageError(with_context(context, e.what()));
    }
  }
  return rgb;
}

std::vector<Stimulus> read_stimuli(std::istream& in, const std::string& source_name,
                                   const Formats& formats) {
  std::vector<Stimulus> stimuli;
  std::string line;
  std::size_t line_number = 0;
  bool header_allowed = true;
  const std::string n_range = "[" + std::to_string(n_min) + ", " + std::to_string(n_max) + "]";
  while (std::getline(in, line)) {
    ++line_number;
    const std::string context = source_name + ":" + std::to_string(line_number);
    const std::string content = trim(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    const std::vector<std::string> fields = split(content, ',');
    if (header_allowed && fields.size() == 5 && fields[0] == "cos" && fields[1] == "n" &&
        fields[2] == "r" && fields[3] == "g" && fields[4] == "b") {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (fields.size() != 5)
      throw UsageError(context + ": expected 5 fields 'cos,n,r,g,b', found " +
                       std::to_string(fields.size()) + " in '" + content + "'");
    try {
      const double cos = parse_cos(fields[0]);
      const long long n = parse_integer(fields[1], "n", n_range);
      std::array<long long, 3> rgb{};
      static const char* channels[3] = {"R", "G", "B"};
      for (int ch = 0; ch < 3; ++ch)
        rgb[ch] = parse_integer(fields[2 + ch], channels[ch], rgb_range(formats));
      stimuli.push_back(make_stimulus(formats, cos, n, rgb, ""));
    } catch (const UsageError& e) {
      throw UsageError(context + ": " + e.what());
    }
  }
  if (in.bad()) throw UsageError(source_name + ": read error after line " + std::to_string(line_number));
  return stimuli;
}

std::vector<Stimulus> read_stimuli_file(const std::string& path, const Formats& formats) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw UsageError("--input: '" + path + "' is a directory, not a CSV file");
  std::ifstream file(path);
  if (!file)
    throw UsageError("--input: cannot open '" + path + "': " + std::strerror(errno));
  std::vector<Stimulus> stimuli = read_stimuli(file, path, formats);
  if (stimuli.empty())
    throw UsageError("--input: '" + path + "' holds no operations (expected lines 'cos,n,r,g,b')");
  return stimuli;
}

std::vector<code_t> sweep_cos_codes(const Formats& formats) {
  const code_t one = formats.cos.one();
  const int frac_bits = formats.cos.frac_bits;
  std::vector<code_t> codes;
  // Uniform part: multiples of 2^-9 (every code if the format is coarser than that).
  const code_t step = frac_bits > 9 ? (code_t{1} << (frac_bits - 9)) : 1;
  for (code_t c = 0; c <= one; c += step) codes.push_back(c);
  // Dense tail: the 512 codes just below 1.
  for (code_t k = 1; k <= 512 && k <= one; ++k) codes.push_back(one - k);
  std::sort(codes.begin(), codes.end());
  codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
  return codes;
}

bool ListSource::next(std::vector<Stimulus>& chunk, std::size_t max) {
  chunk.clear();
  const std::size_t take = std::min(max, stimuli_.size() - position_);
  chunk.insert(chunk.end(), stimuli_.begin() + static_cast<std::ptrdiff_t>(position_),
               stimuli_.begin() + static_cast<std::ptrdiff_t>(position_ + take));
  position_ += take;
  return !chunk.empty();
}

SweepSource::SweepSource(const Formats& formats, const std::array<unsigned, 3>& rgb,
                         const Shard& shard)
    : formats_(formats), rgb_(rgb), cos_codes_(sweep_cos_codes(formats)), shard_(shard) {}

std::size_t SweepSource::size() const {
  std::size_t ns = 0;
  for (unsigned n = n_min; n <= n_max; ++n) ns += shard_has_n(n, shard_) ? 1 : 0;
  return cos_codes_.size() * ns;
}

bool SweepSource::next(std::vector<Stimulus>& chunk, std::size_t max) {
  chunk.clear();
  while (chunk.size() < max && n_ <= n_max) {
    if (!shard_has_n(n_, shard_)) {
      ++n_;
      continue;
    }
    Stimulus s;
    s.index = (n_ - n_min) * cos_codes_.size() + cos_index_;
    s.operands.cos = cos_codes_[cos_index_];
    s.cos = formats_.cos.to_real(s.operands.cos);
    s.n = n_;
    s.operands.n = n_;
    s.rgb = rgb_;
    for (int ch = 0; ch < 3; ++ch) s.operands.rgb[ch] = rgb_[ch];
    chunk.push_back(s);
    if (++cos_index_ == cos_codes_.size()) {
      cos_index_ = 0;
      ++n_;
    }
  }
  return !chunk.empty();
}

RandomSource::RandomSource(const Formats& formats, std::size_t count, std::uint64_t seed,
                           const Shard& shard)
    : formats_(formats),
      begin_(shard_block(count, shard).first),
      end_(shard_block(count, shard).second),
      engine_(seed) {}

std::uint64_t RandomSource::draw(std::uint64_t span) {
  // Rejection sampling: uniform and identical on every platform.
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                              std::numeric_limits<std::uint64_t>::max() % span;
  std::uint64_t value;
  do value = engine_(); while (value >= limit);
  return value % span;
}

bool RandomSource::next(std::vector<Stimulus>& chunk, std::size_t max) {
  chunk.clear();
  const auto rgb_span = static_cast<std::uint64_t>(formats_.rgb.max_code()) + 1;
  const auto cos_span = static_cast<std::uint64_t>(formats_.cos.one()) + 1;
  while (chunk.size() < max && produced_ < end_) {
    Stimulus s;
    s.index = produced_;
    s.operands.cos = static_cast<code_t>(draw(cos_span));
    s.cos = formats_.cos.to_real(s.operands.cos);
    s.n = static_cast<unsigned>(n_min + draw(n_max - n_min + 1));
    s.operands.n = s.n;
    for (int ch = 0; ch < 3; ++ch) {
      s.rgb[ch] = static_cast<unsigned>(draw(rgb_span));
      s.operands.rgb[ch] = s.rgb[ch];
    }
    if (produced_ >= begin_) chunk.push_back(s);  // before the shard's block: drawn, dropped
    ++produced_;
  }
  return !chunk.empty();
}

}  // namespace tb
}  // namespace specular
