#include "scoreboard.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>

#include "run_models.h"

namespace specular {
namespace tb {

std::uint64_t result_hash(std::size_t index, const Result& r, double cycles) {
  std::uint64_t cycle_bits;
  std::memcpy(&cycle_bits, &cycles, sizeof cycle_bits);
  // FNV-1a over the fields' 64-bit values, then a splitmix64 finaliser so that the
  // sum of many hashes stays well mixed.
  std::uint64_t h = 14695981039346656037ull;
  for (const std::uint64_t v :
       {static_cast<std::uint64_t>(index), static_cast<std::uint64_t>(r.reg1),
        static_cast<std::uint64_t>(r.reg9_pass1), static_cast<std::uint64_t>(r.reg9_pass2),
        static_cast<std::uint64_t>(r.rom38_k), static_cast<std::uint64_t>(r.norm39),
        static_cast<std::uint64_t>(r.out[0]), static_cast<std::uint64_t>(r.out[1]),
        static_cast<std::uint64_t>(r.out[2]), cycle_bits})
    for (int byte = 0; byte < 8; ++byte) {
      h ^= (v >> (8 * byte)) & 0xff;
      h *= 1099511628211ull;
    }
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

void Worst::consider(double err, double tolerance, const Comparison& c) {
  if (n == 0 || err > error) {
    error = err;
    cos_q = c.ref.cos_q;
    n = c.stimulus.n;
    at = c.stimulus.index;
  }
  if (tolerance > 0) tolerance_used = std::max(tolerance_used, err / tolerance);
}

Scoreboard::Scoreboard(const Config& config, double latency_cycles)
    : config_(config), formats_(config.widths), latency_cycles_(latency_cycles) {}

Scoreboard Scoreboard::for_variant(const Config& config) {
  Scoreboard board(config, 0.0);
  board.variant_ = true;
  return board;
}

Comparison Scoreboard::compare(const Stimulus& stimulus, const Result& result,
                               double cycles) const {
  Comparison c;
  c.stimulus = stimulus;
  c.result = result;
  c.cycles = cycles;
  // code * 2^-frac, as FixedFormat::to_real computes it with ldexp (a power of two
  // scales exactly), without ldexp's cost on the row path (issue 27).
  const auto real = [](code_t code, const FixedFormat& f) {
    return static_cast<double>(code) * (1.0 / static_cast<double>(std::uint64_t{1} << f.frac_bits));
  };
  const double cos_q = real(result.reg1, formats_.cos);
  const std::array<double, 3> rgb{double(stimulus.rgb[0]), double(stimulus.rgb[1]),
                                  double(stimulus.rgb[2])};
  c.ref = reference::evaluate(cos_q, stimulus.n, rgb, config_.normalisation, config_.saturation,
                              formats_.cos.frac_bits, config_.constants);
  c.k = reference::k(stimulus.n, config_.normalisation, config_.constants, formats_.cos.frac_bits);
  c.approx = real(result.reg9_pass2, formats_.reg9);
  c.norm = real(result.norm39, formats_.norm);
  for (int ch = 0; ch < 3; ++ch) c.out[ch] = real(result.out[ch], formats_.out);

  // Register 1 must hold the code the stimulus asked for, or the reference above
  // would be computed on the wrong input.
  const bool reg1_ok = result.reg1 == stimulus.operands.cos;
  if (variant_) {
    for (int ch = 0; ch < 3; ++ch) c.ref.out_ref[ch] = c.ref.norm_exact * rgb[ch];
    c.approx_ok = c.norm_ok = c.out_ok = reg1_ok;
    c.cycles_ok = true;
    return c;
  }
  c.approx_ok = reg1_ok && std::abs(c.approx - c.ref.approx_ref) <= reference::approx_tolerance();
  c.norm_ok = reg1_ok && std::abs(c.norm - c.ref.norm_ref) <= reference::norm_tolerance(c.k);
  c.out_ok = reg1_ok;
  for (int ch = 0; ch < 3; ++ch)
    c.out_ok = c.out_ok && std::abs(c.out[ch] - c.ref.out_ref[ch]) <=
                               reference::out_tolerance(c.k, rgb[ch], formats_.out.lsb());
  c.cycles_ok = cycles == latency_cycles_;
  return c;
}

void Scoreboard::record(const Comparison& c) {
  Summary& s = summary_;
  if (s.count == 0) s.cycles_min = s.cycles_max = c.cycles;
  ++s.count;
  if (!c.pass()) ++s.failures;
  if (!c.approx_ok) ++s.approx_failures;
  if (!c.norm_ok) ++s.norm_failures;
  if (!c.out_ok) ++s.out_failures;
  if (!c.cycles_ok) ++s.cycles_failures;
  if (!variant_) s.approx.consider(std::abs(c.approx - c.ref.approx_ref), reference::approx_tolerance(), c);
  // A variant's report has no bounds: its errors' share of one stays 0.
  s.norm.consider(std::abs(c.norm - c.ref.norm_ref), variant_ ? 0.0 : reference::norm_tolerance(c.k), c);
  s.norm_exact.consider(std::abs(c.norm - c.ref.norm_exact), 0.0, c);
  for (int ch = 0; ch < 3; ++ch)
    s.out.consider(std::abs(c.out[ch] - c.ref.out_ref[ch]),
                   variant_ ? 0.0 : reference::out_tolerance(c.k, c.stimulus.rgb[ch], formats_.out.lsb()), c);
  s.cycles_min = std::min(s.cycles_min, c.cycles);
  s.cycles_max = std::max(s.cycles_max, c.cycles);
  s.checksum += result_hash(c.stimulus.index, c.result, c.cycles);
}

}  // namespace tb
}  // namespace specular
