// Where the testbench's operations come from: one point, a CSV file, the sweep grid
// or a seeded random draw. Every value is checked here, before any SystemC object
// exists, so a bad input never reaches the kernel.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "shard.h"
#include "specular/core.h"

namespace specular {
namespace tb {

/// One operation as the user asked for it, and the register codes it becomes.
struct Stimulus {
  double cos = 0;                  ///< cos λ as given (before quantisation)
  unsigned n = 1;
  std::array<unsigned, 3> rgb{};   ///< R, G, B intensities
  Operands operands;               ///< registers 1, 2, 10–12 (cos quantised)
  std::size_t index = 0;           ///< its place in the unsharded run (0-based; shard.h)
};

/// Checks and quantises user values with the core's formats (throws UsageError with
/// `context` — e.g. "--n" or "file.csv:12" — in front of the range message).
Stimulus make_stimulus(const Formats& formats, double cos, long long n,
                       const std::array<long long, 3>& rgb, const std::string& context);

/// Parses "R,G,B" (three integers in the RGB format's range).
std::array<long long, 3> parse_rgb_triplet(const std::string& text, const Formats& formats,
                                           const std::string& context);

/// Reads CSV lines `cos,n,r,g,b`. Blank lines, `#` comments (whole-line or trailing)
/// and one optional header line `cos,n,r,g,b` are skipped; blanks around fields and
/// CR line ends are allowed. Any other line that is not five valid fields throws
/// UsageError naming `source_name` and the line number.
std::vector<Stimulus> read_stimuli(std::istream& in, const std::string& source_name,
                                   const Formats& formats);
/// The same from a file; an unreadable or missing file, or one with no operations,
/// throws UsageError.
std::vector<Stimulus> read_stimuli_file(const std::string& path, const Formats& formats);

/// The cos λ grid of --sweep, as register-1 codes (U1.F, 1.0 = 2^F), sorted, unique:
///   - uniform: every multiple of 2^-9 in [0, 1] (513 values, 0 and 1 included);
///   - tail: every one of the 512 codes just below 1 (1 − k·2^-F, k = 1..512),
///     where n·log2 cos λ amplifies the first pass's error most.
/// 1021 values at the default F = 16; with n = 1..1000, 1 021 000 operations.
std::vector<code_t> sweep_cos_codes(const Formats& formats);

/// A stream of stimuli handed out in chunks, so a million-operation run keeps
/// memory flat.
class StimulusSource {
 public:
  virtual ~StimulusSource() = default;
  /// Replaces `chunk` with up to `max` next stimuli; false when none are left.
  virtual bool next(std::vector<Stimulus>& chunk, std::size_t max) = 0;
  /// Total number of stimuli the source yields.
  virtual std::size_t size() const = 0;
};

/// A fixed list (one point, or a file).
class ListSource : public StimulusSource {
 public:
  explicit ListSource(std::vector<Stimulus> stimuli) : stimuli_(std::move(stimuli)) {}
  bool next(std::vector<Stimulus>& chunk, std::size_t max) override;
  std::size_t size() const override { return stimuli_.size(); }

 private:
  std::vector<Stimulus> stimuli_;
  std::size_t position_ = 0;
};

/// n = 1..1000 (outer) × sweep_cos_codes (inner), one RGB for all. The inner loop
/// over cos λ lets the pin harness start every 2 T (register 2 stays loaded).
/// A shard runs the n of its share (shard.h).
class SweepSource : public StimulusSource {
 public:
  SweepSource(const Formats& formats, const std::array<unsigned, 3>& rgb, const Shard& shard = {});
  bool next(std::vector<Stimulus>& chunk, std::size_t max) override;
  std::size_t size() const override;

 private:
  Formats formats_;
  std::array<unsigned, 3> rgb_;
  std::vector<code_t> cos_codes_;
  Shard shard_;
  unsigned n_ = n_min;
  std::size_t cos_index_ = 0;
};

/// `count` operations drawn from a 64-bit Mersenne Twister seeded with `seed`:
/// cos code uniform in [0, 2^F], n uniform in 1..1000, R, G, B uniform in the RGB
/// range. The draws use the raw engine output (not std::uniform_int_distribution,
/// whose algorithm differs between standard libraries), so a seed gives the same
/// operations on every platform. A shard draws every operation before its block and
/// drops it (shard.h), so its draws are the unsharded run's.
class RandomSource : public StimulusSource {
 public:
  RandomSource(const Formats& formats, std::size_t count, std::uint64_t seed, const Shard& shard = {});
  bool next(std::vector<Stimulus>& chunk, std::size_t max) override;
  std::size_t size() const override { return end_ - begin_; }

 private:
  std::uint64_t draw(std::uint64_t span);  // uniform in [0, span)
  Formats formats_;
  std::size_t begin_, end_;                // the shard's block of the count
  std::size_t produced_ = 0;
  std::mt19937_64 engine_;
};

}  // namespace tb
}  // namespace specular
