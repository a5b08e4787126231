// A design variant's exhaustive error (issue 26): every cos code 0..65536 × every n of
// a range (1..1000 by default) at the default configuration and R = G = B = 255, the
// variant's lobe against K(n)·cos_q^n and its pins 24–26 against K(n)·cos_q^n·255:
// max and mean |error| and where the max occurs; also against the patent's formula in
// double (docs/accuracy.md's norm_ref: the reference of the variants that compute it).
//
// Sharded by n as specular_tb --sweep is ((n − 1) mod N == I), with partial results
// that merge into exactly the unsharded run's figures: each n's sums are kept apart and
// added in n order, and a maximum's ties go to the smallest (n, cos code), the first one
// the unsharded run meets.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "json.h"
#include "shard.h"

namespace specular {
namespace tb {

/// The partial file's "kind" (read_complete_set, partial.h).
constexpr const char* variant_error_kind = "specular_variant_error partial result";

/// One error measure over a run: its maximum and where, and each n's sum of |error|.
struct ErrorMeasure {
  double max_abs = -1;              ///< −1: nothing measured yet
  long long max_cos_code = 0;       ///< the max's cos code (register 1, U1.16) …
  unsigned max_n = 0;               ///< … and n
  std::vector<double> sum_by_n;     ///< index n (0 unused): Σ |error| over that n's values
  std::uint64_t values = 0;         ///< how many |error|s the sums hold
  /// Adds |error| at (cos code, n); the sums are summed in n order by mean_abs().
  void add(double error, long long cos_code, unsigned n);
  /// Takes in another shard's measure (its n are not this one's).
  void merge(const ErrorMeasure& other);
  double mean_abs() const;
};

/// What the run covers.
struct ErrorSweepRange {
  unsigned n_first = 1, n_last = 1000;
  Shard shard{};
};

struct VariantError {
  std::string name;
  ErrorSweepRange range;
  std::uint64_t operations = 0;
  ErrorMeasure lobe;          ///< |lobe − K(n)·cos_q^n|
  ErrorMeasure out;           ///< |pin − K(n)·cos_q^n·255|, each of pins 24–26
  bool has_formula = false;   ///< also against the patent's formula (every run; a partial says)
  ErrorMeasure formula_lobe;  ///< |lobe − norm_ref| (K(n)·A in double)
  ErrorMeasure formula_out;   ///< |pin − out_ref|
  double seconds = 0;         ///< wall time (a merge: the shards' sum)
};

/// Runs the sweep of `range` on variant `name` (make_variant at the default Config).
/// Throws std::invalid_argument for an unknown name.
VariantError measure_variant_error(const std::string& name, const ErrorSweepRange& range);

/// The report: name, lobe_max_abs, lobe_mean_abs, lobe_max_at {cos_code, n}, out_…,
/// operations, seconds, and "patent_formula" with the same fields against K(n)·A.
Json variant_error_json(const VariantError& e);

/// A shard's partial result: settings (name, n range), shard, the measures with their
/// per-n sums, timing; merge_variant_error() reads a complete set of them.
Json variant_error_partial(const VariantError& e);
/// Merges partial files (every shard once, one run): throws UsageError naming the file.
VariantError merge_variant_error(const std::vector<std::string>& files);

/// The command line: `NAME [--json FILE] [--n FIRST:LAST] [--shard I/N --partial FILE]`,
/// `--merge FILE... [--json FILE]`, `--all [--json FILE] [--n FIRST:LAST]`, `--list`, `--help`. Returns the exit status.
int run_variant_error(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace tb
}  // namespace specular
