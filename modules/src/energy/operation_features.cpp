#include "specular/energy/operation_features.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "specular/constants.h"

namespace specular::energy {

// The features the gate-level fit gives weight to (docs/energy/calibration.md lists the
// ones it was offered and held at 0: register 1's and register 9's own toggles, the
// loads, multiplier 6's second operand, ...).
const std::array<const char*, feature_count> feature_names = {
    "one",                        // every operation (the fit holds it at 0)
    "toggles_reg2",               // register 2 (n)
    "rom38_read",                 // n changed: ROM 38 reads a new word
    "toggles_rgb",                // registers 10-12
    "start_mul6",                 // from the start to pass 1 written: multiplier 6's product
    "start_mul_rgb",              //   multipliers 13-15's products
    "start_mul39_activity",       //   multiplier 39's partial products that move
    "start_mul_rgb_activity",     //   multipliers 13-15's partial products that move
    "end_rom5_read",              // pass 2 written: ROM 5's address changes (1) or not (0)
    "end_log2",                   //   the log2 unit's output
    "end_mul6",                   //   multiplier 6's product
    "end_mul_rgb_activity",       //   multipliers 13-15's partial products that move
    "prev_end_log2",              // the previous operation's pass 2 written: the log2 unit
    "prev_end_mul6",              //   multiplier 6's product
    "prev_end_mul39_activity",    //   multiplier 39's partial products that move
    "prev_end_mul_rgb_activity",  //   multipliers 13-15's
    "idle_rom5_read",             // Fig. 2 between operations: a new cos on ROM 5's bus
    "idle_mul6_activity",         //   multiplier 6's partial products that move (on n)
    "return_rom5_read",           // Fig. 2's select 36 falling after pass 2: ROM 5's bus back
    "return_mul6_activity",       //   to register 1, multiplier 6's operand back to n
    "prev_return_rom5_read",      // the previous operation's return
    "prev_return_mul6_activity",
    "ones_norm39",                // the result's ones: multiplier 39's product K·A
    "ones_out",                   //   and pins 24-26
};

namespace {

// The helpers are inlined into the stream's step, so that its POPCNT clone uses the
// instruction for them too.
#define SPECULAR_ENERGY_INLINE inline __attribute__((always_inline))

// The features are counted in integers (activities in eighths) and turned into doubles
// once per operation: the same values, in half the instructions of counting in doubles.

/// Bits that differ between two codes on a bus of `width` bits.
SPECULAR_ENERGY_INLINE int toggles(code_t a, code_t b, int width) {
  const std::uint64_t mask = width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
  return __builtin_popcountll((static_cast<std::uint64_t>(a) ^ static_cast<std::uint64_t>(b)) & mask);
}

/// Ones of a code on a bus of `width` bits.
SPECULAR_ENERGY_INLINE int ones(code_t a, int width) { return toggles(a, 0, width); }

/// An array multiplier's activity from operands (a0, b0) to (a1, b1), in eighths: each
/// operand's toggles times the ones of the other (the partial products that change).
SPECULAR_ENERGY_INLINE int activity8(code_t a0, code_t b0, code_t a1, code_t b1, int wa, int wb) {
  return toggles(a0, a1, wa) * ones(b1, wb) + toggles(b0, b1, wb) * ones(a1, wa);
}

/// Eighths as the feature's value.
SPECULAR_ENERGY_INLINE double eighths(int count) { return count / 8.0; }

/// ROM 5's address for a multiplexer-3 code: the exponent (the leading one's place)
/// and the mantissa bits after it, as Rom5Table::lookup forms them; a code ≤ 0 reads
/// the table's zero entry.
template <class FormatSet>
SPECULAR_ENERGY_INLINE code_t rom5_address(const FormatSet& f, code_t bus) {
  if (bus <= 0) return 0;
  const int bits = f.widths.rom5_addr_bits;
  const arith::LeadingOne one = arith::leading_one(static_cast<std::uint64_t>(bus), 64);
  return static_cast<code_t>((static_cast<std::uint64_t>(one.msb) << bits) |
                             arith::Rom5Table::mantissa_address(one, bits));
}

/// ROM 5's table for `f`, one per widths for the whole process (the default widths in
/// practice): streams share it, so that its words stay in the cache once.
const arith::Rom5Table& shared_rom5(const Formats& f) {
  static std::mutex mutex;
  static std::vector<std::pair<Widths, std::unique_ptr<arith::Rom5Table>>> tables;
  const std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [widths, table] : tables)
    if (std::memcmp(&widths, &f.widths, sizeof(Widths)) == 0) return *table;
  tables.emplace_back(f.widths, std::make_unique<arith::Rom5Table>(f));
  return *tables.back().second;
}

using Settled = FeatureStream::Settled;

template <class FormatSet>
SPECULAR_ENERGY_INLINE Settled settle(const FormatSet& f, const arith::Rom5Table& rom5, code_t h,
                                      const RegisterState& s) {
  const Operands& in = s.in;
  const Result& r = s.r;
  Settled out;
  out.regs = s;
  const code_t bus_cos = arith::mux3(f, false, in.cos, 0);
  out.log_cos = rom5.log2(f, bus_cos);
  out.rom5_cos = rom5_address(f, bus_cos);
  out.n_operand = arith::mux4(f, false, in.n, h);
  out.log_pass1 = rom5.log2(f, r.reg9_pass1);
  out.mul6_pass1 = arith::mul6(f, out.log_pass1, h);
  out.mul39_pass1 = arith::mul39(f, r.reg9_pass1, r.rom38_k);
  out.log_pass2 = rom5.log2(f, r.reg9_pass2);
  out.rom5_pass2 = rom5_address(f, r.reg9_pass2);
  out.mul6_pass2 = arith::mul6(f, out.log_pass2, h);
  out.end_rom5_read = rom5_address(f, r.reg9_pass1) != out.rom5_pass2;
  out.end_log2 = toggles(out.log_pass1, out.log_pass2, f.log2.width());
  out.end_mul6 = toggles(out.mul6_pass1, out.mul6_pass2, f.reg9.width());
  out.end_mul39_activity8 = activity8(r.reg9_pass1, r.rom38_k, r.reg9_pass2, r.rom38_k, f.reg9.width(), f.rom38.width());
  int rgb_activity8 = 0;
  for (int ch = 0; ch < 3; ++ch)
    rgb_activity8 += activity8(out.mul39_pass1, in.rgb[ch], r.norm39, in.rgb[ch], f.norm.width(), f.rgb.width());
  out.end_mul_rgb_activity8 = rgb_activity8;
  out.return_rom5_read = out.rom5_pass2 != out.rom5_cos;
  out.return_mul6_activity8 = activity8(out.log_pass2, h, out.log_cos, out.n_operand, f.log2.width(), f.mux4.width());
  return out;
}

// An operation takes the datapath through three states from the previous operation's
// end (select 36 high, register 9 its pass 2): the new operands loaded (pass 1 on
// register 1), pass 1 written (pass 2 on register 9), pass 2 written (the result). A
// bus's bits that change between them are what its fan-out recomputes; the
// combinational buses (the log2 unit, the multipliers) are taken at their settled
// values, a multiplier's glitches by its activity. The last step is given twice, the
// operation's own and the previous operation's: the gate-level replays count an
// operation from one result strobe to the next, and where that strobe falls decides
// which of the two the interval holds (docs/energy/calibration.md).
template <class FormatSet>
SPECULAR_ENERGY_INLINE Features step(const FormatSet& f, const Settled& pa, const Settled& pb) {
  const Operands& a = pa.regs.in;
  const Operands& b = pb.regs.in;
  const Result& ra = pa.regs.r;
  const Result& rb = pb.regs.r;
  const int reg9 = f.reg9.width();
  // From the start to pass 1 written: ROM 5's bus from the last pass 2 to register 1 to
  // pass 1, multiplier 6's second operand h, n, h.
  const code_t mul6_cos = arith::mul6(f, pb.log_cos, pb.n_operand);
  // Multiplier 39: the last pass 2 times the new n's word, then pass 1.
  const code_t mul39_new_k = arith::mul39(f, ra.reg9_pass2, rb.rom38_k);
  int rgb = 0, mul_rgb = 0, rgb_activity8 = 0, out_ones = 0;
  for (int ch = 0; ch < 3; ++ch) {
    rgb += toggles(a.rgb[ch], b.rgb[ch], f.rgb.width());
    const code_t p1 = arith::mul_rgb(f, mul39_new_k, b.rgb[ch]), p2 = arith::mul_rgb(f, pb.mul39_pass1, b.rgb[ch]);
    mul_rgb += toggles(ra.out[ch], p1, f.out.width()) + toggles(p1, p2, f.out.width());
    rgb_activity8 += activity8(ra.norm39, a.rgb[ch], mul39_new_k, b.rgb[ch], f.norm.width(), f.rgb.width()) +
                     activity8(mul39_new_k, b.rgb[ch], pb.mul39_pass1, b.rgb[ch], f.norm.width(), f.rgb.width());
    out_ones += ones(rb.out[ch], f.out.width());
  }
  const int mul39_activity8 =
      activity8(ra.reg9_pass2, ra.rom38_k, ra.reg9_pass2, rb.rom38_k, reg9, f.rom38.width()) +
      activity8(ra.reg9_pass2, rb.rom38_k, rb.reg9_pass1, rb.rom38_k, reg9, f.rom38.width());
  return Features{
      1.0,
      double(toggles(a.n, b.n, f.n.width())),
      double(a.n != b.n),
      double(rgb),
      double(toggles(pa.mul6_pass2, mul6_cos, reg9) + toggles(mul6_cos, pb.mul6_pass1, reg9)),
      double(mul_rgb),
      eighths(mul39_activity8),
      eighths(rgb_activity8),
      double(pb.end_rom5_read),
      double(pb.end_log2),
      double(pb.end_mul6),
      eighths(pb.end_mul_rgb_activity8),
      double(pa.end_log2),
      double(pa.end_mul6),
      eighths(pa.end_mul39_activity8),
      eighths(pa.end_mul_rgb_activity8),
      // Fig. 2 between operations: register 1 and register 2 on multiplexers 3 and 4.
      double(pa.rom5_cos != pb.rom5_cos),
      eighths(activity8(pa.log_cos, pa.n_operand, pb.log_cos, pb.n_operand, f.log2.width(), f.mux4.width())),
      double(pb.return_rom5_read),
      eighths(pb.return_mul6_activity8),
      double(pa.return_rom5_read),
      eighths(pa.return_mul6_activity8),
      double(ones(rb.norm39, f.norm.width())),
      double(out_ones),
  };
}

// Hardware POPCNT where the CPU has it (every x86-64 since 2008), chosen once at load
// time: libgcc's portable popcount costs more than the rest of an operation's features.
// Two instantiations: the default widths on DefaultFormats' constants, any other on the
// run-time Formats.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SPECULAR_ENERGY_POPCNT __attribute__((target_clones("popcnt", "default")))
#else
#define SPECULAR_ENERGY_POPCNT
#endif

SPECULAR_ENERGY_POPCNT void step_default(const Settled& last, Settled& next, const RegisterState& s,
                                         const arith::Rom5Table& rom5, code_t h, Features& x) {
  const DefaultFormats f;
  next = settle(f, rom5, h, s);
  x = step(f, last, next);
}

SPECULAR_ENERGY_POPCNT void step_formats(const Formats& f, const Settled& last, Settled& next,
                                         const RegisterState& s, const arith::Rom5Table& rom5, code_t h,
                                         Features& x) {
  next = settle(f, rom5, h, s);
  x = step(f, last, next);
}

Settled settle_any(const Formats& f, bool default_formats, const arith::Rom5Table& rom5, code_t h,
                   const RegisterState& s) {
  return default_formats ? settle(DefaultFormats{}, rom5, h, s) : settle(f, rom5, h, s);
}

}  // namespace

FeatureStream::FeatureStream(const Formats& formats)
    : formats_(formats),
      default_formats_(has_default_formats(formats)),
      pin19_h_(pin19_code(formats, Constants::patent)),
      rom5_(&shared_rom5(formats)) {
  restart_from(reset_state());
}

Features FeatureStream::next(const Operands& in, const Result& r) {
  const Settled& last = settled_[last_];
  Settled& next = settled_[1 - last_];
  const RegisterState s{in, r};
  Features x;
  if (default_formats_) step_default(last, next, s, *rom5_, pin19_h_, x);
  else step_formats(formats_, last, next, s, *rom5_, pin19_h_, x);
  last_ = 1 - last_;
  return x;
}

void FeatureStream::restart_from(const RegisterState& registers) {
  settled_[last_] = settle_any(formats_, default_formats_, *rom5_, pin19_h_, registers);
}

Features operation_features(const Formats& f, const RegisterState& before, const RegisterState& after) {
  FeatureStream stream(f);
  stream.restart_from(before);
  return stream.next(after.in, after.r);
}

}  // namespace specular::energy
