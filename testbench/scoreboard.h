// Compares each result of the device with the double-precision reference and keeps
// the run's summary: worst errors and where they occur, failures, pass/fail.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "input.h"
#include "specular/core.h"
#include "run_models.h"
#include "specular/reference.h"

namespace specular {
namespace tb {

/// The hash Summary::checksum adds for one computation.
std::uint64_t result_hash(std::size_t index, const Result& result, double cycles);

/// One computation as reported: what went in, what the device held, the reference.
struct Comparison {
  Stimulus stimulus;
  Result result;                  ///< codes from the model
  double cycles = 0;              ///< start → 35↑, clock periods
  double k = 0;                   ///< K(n) in double under the policy
  reference::Figures ref;         ///< cos_q, approx_ref, norm_ref, norm_exact, out_ref
  double approx = 0;              ///< register 9 after pass 2, as a real
  double norm = 0;                ///< multiplier 39, as a real
  std::array<double, 3> out{};    ///< pins 24–26, as reals in units of R, G, B
  bool approx_ok = false;         ///< |approx − approx_ref| ≤ 2^-10
  bool norm_ok = false;           ///< |norm − norm_ref| ≤ 2^-10·max(1, K)
  bool out_ok = false;            ///< every channel: ≤ 2^-10·max(1, K)·I + 1 LSB
  bool cycles_ok = false;         ///< the spec's 2.5 periods
  bool pass() const { return approx_ok && norm_ok && out_ok && cycles_ok; }
};

/// The largest |error| of one kind over a run, and where it occurred.
struct Worst {
  double error = 0;               ///< largest |model − reference|
  double cos_q = 0;               ///< at this cos λ (as held in register 1) …
  unsigned n = 0;                 ///< … and this n (0: no computation yet)
  std::size_t at = 0;             ///< … the operation's index in the unsharded run (the
                                  ///< first one with this error: a merge's tie-break)
  double tolerance_used = 0;      ///< largest error/tolerance (1 = at the bound)
  void consider(double err, double tolerance, const Comparison& c);
};

struct Summary {
  std::size_t count = 0;
  std::size_t failures = 0;       ///< computations with any comparison out of tolerance
  std::size_t approx_failures = 0, norm_failures = 0, out_failures = 0, cycles_failures = 0;
  Worst approx;                   ///< |approx − approx_ref|
  Worst norm;                     ///< |norm − norm_ref|
  Worst norm_exact;               ///< |norm − norm_exact| (the formula's own error; no bound)
  Worst out;                      ///< max over channels of |out − out_ref|
  double cycles_min = 0, cycles_max = 0;
  /// Sum (mod 2^64) over the computations of a hash of (index, every result code,
  /// cycles): independent of order, so the shards' checksums add up to the whole run's.
  std::uint64_t checksum = 0;
  std::vector<std::string> failure_traces;  ///< --trace-failures: the files written
  std::size_t failure_traces_left_out = 0;  ///< failures past --trace-failures-max
  /// Issue 61: the operations' energy in pJ, as the model's device spends it at gate
  /// level (energy::OperationEnergy; 0 for a design variant, which has no figures).
  double energy_pj = 0;
  /// tlm: the rest of the TLM target's energy (register reads and writes, clocks).
  double energy_bus_pj = 0;
  bool pass() const { return count > 0 && failures == 0; }
};

class Scoreboard {
 public:
  /// `latency_cycles`: start → 35↑ a result must show (the spec's 2.5 T by default;
  /// the synchronous variant's 2 T, latency_cycles(Model::rtl_sync)).
  explicit Scoreboard(const Config& config, double latency_cycles = spec_latency_cycles);
  /// A design variant's scoreboard (specular_tb --variant, issue 26): the lobe (norm)
  /// against norm_exact = K(n)·cos_q^n and against the patent formula's norm_ref, pins
  /// 24–26 against norm_exact·I (out_ref becomes that), no approx (no register 9), no
  /// latency (no clock). Report only: every check passes while register 1 holds the
  /// stimulus's code (each variant's bound is its own, docs/variants/NAME.md).
  static Scoreboard for_variant(const Config& config);
  bool variant() const { return variant_; }
  /// Compares one result with the reference (does not record it).
  Comparison compare(const Stimulus& stimulus, const Result& result, double cycles) const;
  /// Adds a comparison to the summary.
  void record(const Comparison& c);
  const Summary& summary() const { return summary_; }
  Summary& summary() { return summary_; }
  const Formats& formats() const { return formats_; }
  const Config& config() const { return config_; }

 private:
  Config config_;
  Formats formats_;
  double latency_cycles_;
  bool variant_ = false;
  Summary summary_;
};

}  // namespace tb
}  // namespace specular
