#include "specular/energy/operation_features.h"

#include <cstdint>
#include <cstring>
#include <memory>

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

// The helpers are inlined into operation_features, so that its POPCNT clone uses the
// instruction for them too.
#define SPECULAR_ENERGY_INLINE inline __attribute__((always_inline))

/// Bits that differ between two codes on a bus of `width` bits.
SPECULAR_ENERGY_INLINE double toggles(code_t a, code_t b, int width) {
  const std::uint64_t mask = width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
  return static_cast<double>(__builtin_popcountll((static_cast<std::uint64_t>(a) ^ static_cast<std::uint64_t>(b)) & mask));
}

/// Ones of a code on a bus of `width` bits.
SPECULAR_ENERGY_INLINE double ones(code_t a, int width) { return toggles(a, 0, width); }

/// An array multiplier's activity from operands (a0, b0) to (a1, b1): each operand's
/// toggles times the ones of the other (the partial products that change), / 8.
SPECULAR_ENERGY_INLINE double activity(code_t a0, code_t b0, code_t a1, code_t b1, int wa, int wb) {
  return (toggles(a0, a1, wa) * ones(b1, wb) + toggles(b0, b1, wb) * ones(a1, wa)) / 8.0;
}

/// ROM 5's address for a multiplexer-3 code: the exponent (the leading one's place)
/// and the mantissa bits after it, as Rom5Table::lookup forms them; a code ≤ 0 reads
/// the table's zero entry.
SPECULAR_ENERGY_INLINE code_t rom5_address(const Formats& f, code_t bus) {
  if (bus <= 0) return 0;
  const int bits = f.widths.rom5_addr_bits;
  const arith::LeadingOne one = arith::leading_one(static_cast<std::uint64_t>(bus), 64);
  const std::uint64_t mantissa = (one.normalised << 1) >> (64 - bits);
  return static_cast<code_t>((static_cast<std::uint64_t>(one.msb) << bits) | mantissa);
}

/// ROM 5's table for `f` (built once per thread and widths: the default widths in practice).
const arith::Rom5Table& rom5_for(const Formats& f) {
  thread_local Widths widths{};
  thread_local std::unique_ptr<arith::Rom5Table> table;
  if (!table || std::memcmp(&widths, &f.widths, sizeof(Widths)) != 0) {
    table = std::make_unique<arith::Rom5Table>(f);
    widths = f.widths;
  }
  return *table;
}

/// Pass 2 written (register 9 from pass 1 to pass 2, select 36 high): ROM 5's read, the
/// log2 unit's and multiplier 6's (on h) toggles, multipliers 13-15's activity as
/// multiplier 39 settles on the result.
struct End {
  double rom5_read, log2, mul6, mul39_activity, mul_rgb_activity;
};
SPECULAR_ENERGY_INLINE End end_of(const Formats& f, const arith::Rom5Table& rom5, code_t h,
                                  const Operands& in, const Result& r) {
  const code_t log1 = rom5.log2(r.reg9_pass1), log2 = rom5.log2(r.reg9_pass2);
  const code_t mul39_pass1 = arith::mul39(f, r.reg9_pass1, r.rom38_k);
  double rgb_activity = 0;
  for (int ch = 0; ch < 3; ++ch)
    rgb_activity += activity(mul39_pass1, in.rgb[ch], r.norm39, in.rgb[ch], f.norm.width(), f.rgb.width());
  return {rom5_address(f, r.reg9_pass1) != rom5_address(f, r.reg9_pass2) ? 1.0 : 0.0,
          toggles(log1, log2, f.log2.width()),
          toggles(arith::mul6(f, log1, h), arith::mul6(f, log2, h), f.reg9.width()),
          activity(r.reg9_pass1, r.rom38_k, r.reg9_pass2, r.rom38_k, f.reg9.width(), f.rom38.width()),
          rgb_activity};
}

/// Fig. 2's select 36 falls after pass 2 is written: ROM 5's bus from register 9's pass 2
/// back to register 1's cos, multiplier 6's second operand from h back to n.
struct Return {
  double rom5_read, mul6_activity;
};
SPECULAR_ENERGY_INLINE Return return_of(const Formats& f, const arith::Rom5Table& rom5, code_t h,
                                        const Operands& in, const Result& r) {
  const code_t bus = arith::mux3(f, false, in.cos, 0), n = arith::mux4(f, false, in.n, h);
  return {rom5_address(f, r.reg9_pass2) != rom5_address(f, bus) ? 1.0 : 0.0,
          activity(rom5.log2(r.reg9_pass2), h, rom5.log2(bus), n, f.log2.width(), f.mux4.width())};
}

}  // namespace

// An operation takes the datapath through three states from the previous operation's
// end (select 36 high, register 9 its pass 2): the new operands loaded (pass 1 on
// register 1), pass 1 written (pass 2 on register 9), pass 2 written (the result). A
// bus's bits that change between them are what its fan-out recomputes; the
// combinational buses (the log2 unit, the multipliers) are taken at their settled
// values, a multiplier's glitches by its activity. The last step is given twice, the
// operation's own and the previous operation's: the gate-level replays count an
// operation from one result strobe to the next, and where that strobe falls decides
// which of the two the interval holds (docs/energy/calibration.md).
//
// Hardware POPCNT where the CPU has it (every x86-64 since 2008), chosen once at load
// time: libgcc's portable popcount costs more than the rest of an operation's features.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("popcnt", "default")))
#endif
Features operation_features(const Formats& f, const RegisterState& before, const RegisterState& after) {
  const Operands& a = before.in;
  const Operands& b = after.in;
  const Result& ra = before.r;
  const Result& rb = after.r;
  const int reg9 = f.reg9.width();
  const arith::Rom5Table& rom5 = rom5_for(f);
  const code_t h = pin19_code(f, Constants::patent);
  // From the start to pass 1 written: ROM 5's bus from the last pass 2 to register 1 to
  // pass 1, multiplier 6's second operand h, n, h.
  const code_t log_end = rom5.log2(ra.reg9_pass2), log_cos = rom5.log2(arith::mux3(f, false, b.cos, 0));
  const code_t log_pass1 = rom5.log2(rb.reg9_pass1);
  const code_t n = arith::mux4(f, false, b.n, h);
  const code_t mul6_end = arith::mul6(f, log_end, h), mul6_cos = arith::mul6(f, log_cos, n);
  const code_t mul6_pass1 = arith::mul6(f, log_pass1, h);
  // Multiplier 39: the last pass 2 times the new n's word, then pass 1.
  const code_t mul39_new_k = arith::mul39(f, ra.reg9_pass2, rb.rom38_k);
  const code_t mul39_pass1 = arith::mul39(f, rb.reg9_pass1, rb.rom38_k);
  double rgb = 0, mul_rgb = 0, rgb_activity = 0, out_ones = 0;
  for (int ch = 0; ch < 3; ++ch) {
    rgb += toggles(a.rgb[ch], b.rgb[ch], f.rgb.width());
    const code_t p1 = arith::mul_rgb(f, mul39_new_k, b.rgb[ch]), p2 = arith::mul_rgb(f, mul39_pass1, b.rgb[ch]);
    mul_rgb += toggles(ra.out[ch], p1, f.out.width()) + toggles(p1, p2, f.out.width());
    rgb_activity += activity(ra.norm39, a.rgb[ch], mul39_new_k, b.rgb[ch], f.norm.width(), f.rgb.width()) +
                    activity(mul39_new_k, b.rgb[ch], mul39_pass1, b.rgb[ch], f.norm.width(), f.rgb.width());
    out_ones += ones(rb.out[ch], f.out.width());
  }
  const double mul39_activity =
      activity(ra.reg9_pass2, ra.rom38_k, ra.reg9_pass2, rb.rom38_k, reg9, f.rom38.width()) +
      activity(ra.reg9_pass2, rb.rom38_k, rb.reg9_pass1, rb.rom38_k, reg9, f.rom38.width());
  const End end = end_of(f, rom5, h, b, rb);
  const End prev_end = end_of(f, rom5, h, a, ra);
  const Return ret = return_of(f, rom5, h, b, rb);
  const Return prev_ret = return_of(f, rom5, h, a, ra);
  // Fig. 2 between operations: register 1 and register 2 on multiplexers 3 and 4.
  const code_t bus_a = arith::mux3(f, false, a.cos, 0);
  return Features{
      1.0,
      toggles(a.n, b.n, f.n.width()),
      a.n != b.n ? 1.0 : 0.0,
      rgb,
      toggles(mul6_end, mul6_cos, reg9) + toggles(mul6_cos, mul6_pass1, reg9),
      mul_rgb,
      mul39_activity,
      rgb_activity,
      end.rom5_read,
      end.log2,
      end.mul6,
      end.mul_rgb_activity,
      prev_end.log2,
      prev_end.mul6,
      prev_end.mul39_activity,
      prev_end.mul_rgb_activity,
      rom5_address(f, bus_a) != rom5_address(f, arith::mux3(f, false, b.cos, 0)) ? 1.0 : 0.0,
      activity(rom5.log2(bus_a), arith::mux4(f, false, a.n, h), log_cos, n, f.log2.width(), f.mux4.width()),
      ret.rom5_read,
      ret.mul6_activity,
      prev_ret.rom5_read,
      prev_ret.mul6_activity,
      ones(rb.norm39, f.norm.width()),
      out_ones,
  };
}

}  // namespace specular::energy
