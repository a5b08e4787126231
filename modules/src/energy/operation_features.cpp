#include "specular/energy/operation_features.h"

#include <cstdint>
#include <cstring>
#include <memory>

#include "specular/constants.h"

namespace specular::energy {

const std::array<const char*, feature_count> feature_names = {
    "one",                   // every operation: the control unit's sequence and the clock
    "toggles_reg1",          // register 1 (cos)
    "toggles_reg2",          // register 2 (n)
    "rom38_read",            // n changed: ROM 38 reads a new word
    "load",                  // n, R, G or B changed: the operand loads and their clock
    "toggles_rgb",           // registers 10-12
    "toggles_mux4",          // multiplier 6's second operand: h, n, h
    "start_reg9",            // the start to pass 1 written: register 9 from the last pass 2
    "start_rom5_reads",      //   ROM 5's address changes (pass 1's cos, pass 1's result)
    "start_log2",            //   the log2 unit's output
    "start_mul6",            //   multiplier 6's product
    "start_mul39",           //   multiplier 39's product (new n's word, then pass 1)
    "start_mul_rgb",         //   multipliers 13-15's products
    "end_reg9",              // pass 2 written: register 9 from pass 1
    "end_rom5_read",         //   ROM 5's address changes (1) or not (0)
    "end_log2",              //   the log2 unit's output
    "end_mul6",              //   multiplier 6's product
    "end_mul39",             //   multiplier 39's product
    "end_mul_rgb",           //   multipliers 13-15's products: the result on pins 24-26
    "prev_end_reg9",         // the same six of the previous operation's pass 2 written
    "prev_end_rom5_read",
    "prev_end_log2",
    "prev_end_mul6",
    "prev_end_mul39",
    "prev_end_mul_rgb",
    "start_mul6_activity",   // multiplier 6's operands: each one's toggles times the other's ones
    "start_mul39_activity",  //   (an array multiplier's partial products that move), /8
    "start_mul_rgb_activity",
    "end_mul6_activity",
    "end_mul39_activity",
    "end_mul_rgb_activity",
    "prev_end_mul6_activity",
    "prev_end_mul39_activity",
    "prev_end_mul_rgb_activity",
    "idle_rom5_read",        // Fig. 2's select 36 low between operations: ROM 5's bus holds
    "idle_log2",             //   register 1, so a new cos moves its address (1) or not (0),
    "idle_mul6",             //   the log2 unit and multiplier 6 (on n) before pass 1
    "idle_mul6_activity",
    "return_rom5_read",      // ... and select 36 falls after pass 2 is written: the bus goes
    "return_log2",           //   back from register 9 to register 1 (the operation's own)
    "return_mul6",
    "return_mul6_activity",
    "prev_return_rom5_read", // the previous operation's, where the replay's interval holds it
    "prev_return_log2",
    "prev_return_mul6",
    "prev_return_mul6_activity",
    "ones_norm39",           // the result's ones: multiplier 39's product K·A
    "ones_out",              //   and pins 24-26 (the lit part of a lobe holds them high)
};

namespace {

/// Bits that differ between two codes on a bus of `width` bits.
double toggles(code_t a, code_t b, int width) {
  const std::uint64_t mask = width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
  return static_cast<double>(__builtin_popcountll((static_cast<std::uint64_t>(a) ^ static_cast<std::uint64_t>(b)) & mask));
}

/// The bits that change along a sequence of values of one bus.
template <std::size_t N>
double sequence_toggles(const std::array<code_t, N>& values, int width) {
  double sum = 0;
  for (std::size_t i = 1; i < N; ++i) sum += toggles(values[i - 1], values[i], width);
  return sum;
}

/// Ones of a code on a bus of `width` bits.
double ones(code_t a, int width) { return toggles(a, 0, width); }

/// An array multiplier's activity from operands (a0, b0) to (a1, b1): each operand's
/// toggles times the ones of the other (the partial products that change), / 8.
double activity(code_t a0, code_t b0, code_t a1, code_t b1, int wa, int wb) {
  return (toggles(a0, a1, wa) * ones(b1, wb) + toggles(b0, b1, wb) * ones(a1, wa)) / 8.0;
}

/// ROM 5's address for a multiplexer-3 code: the exponent (the leading one's place)
/// and the mantissa bits after it, as Rom5Table::lookup forms them; a code ≤ 0 reads
/// the table's zero entry.
code_t rom5_address(const Formats& f, code_t bus) {
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

}  // namespace

namespace {

/// The toggles as pass 2 is written (register 9 from pass 1 to pass 2, select 36 high):
/// register 9, ROM 5's read, the log2 unit, multiplier 6 (on h), multiplier 39 and
/// multipliers 13-15, which then settle on the operation's result.
std::array<double, 9> end_toggles(const Formats& f, const arith::Rom5Table& rom5, code_t h,
                                  const Operands& in, const Result& r) {
  const int reg9 = f.reg9.width();
  const code_t log1 = rom5.log2(r.reg9_pass1), log2 = rom5.log2(r.reg9_pass2);
  const code_t mul39_pass1 = arith::mul39(f, r.reg9_pass1, r.rom38_k);
  double mul_rgb = 0, rgb_activity = 0;
  for (int ch = 0; ch < 3; ++ch) {
    mul_rgb += toggles(arith::mul_rgb(f, mul39_pass1, in.rgb[ch]), r.out[ch], f.out.width());
    rgb_activity += activity(mul39_pass1, in.rgb[ch], r.norm39, in.rgb[ch], f.norm.width(), f.rgb.width());
  }
  return {toggles(r.reg9_pass1, r.reg9_pass2, reg9),
          rom5_address(f, r.reg9_pass1) != rom5_address(f, r.reg9_pass2) ? 1.0 : 0.0,
          toggles(log1, log2, f.log2.width()),
          toggles(arith::mul6(f, log1, h), arith::mul6(f, log2, h), reg9),
          toggles(mul39_pass1, r.norm39, f.norm.width()),
          mul_rgb,
          activity(log1, h, log2, h, f.log2.width(), f.mux4.width()),
          activity(r.reg9_pass1, r.rom38_k, r.reg9_pass2, r.rom38_k, reg9, f.rom38.width()),
          rgb_activity};
}

/// Fig. 2's select 36 falls after pass 2 is written: ROM 5's bus from register 9's pass 2
/// back to register 1's cos, multiplier 6's second operand from h back to n.
std::array<double, 4> return_toggles(const Formats& f, const arith::Rom5Table& rom5, code_t h,
                                     const Operands& in, const Result& r) {
  const code_t bus = arith::mux3(f, false, in.cos, 0), n = arith::mux4(f, false, in.n, h);
  const code_t log_p2 = rom5.log2(r.reg9_pass2), log_cos = rom5.log2(bus);
  return {rom5_address(f, r.reg9_pass2) != rom5_address(f, bus) ? 1.0 : 0.0,
          toggles(log_p2, log_cos, f.log2.width()),
          toggles(arith::mul6(f, log_p2, h), arith::mul6(f, log_cos, n), f.reg9.width()),
          activity(log_p2, h, log_cos, n, f.log2.width(), f.mux4.width())};
}

}  // namespace

// An operation takes the datapath through three states from the previous operation's
// end (select 36 high, register 9 its pass 2): the new operands loaded (pass 1 on
// register 1), pass 1 written (pass 2 on register 9), pass 2 written (the result). A
// bus's bits that change between them are what its fan-out recomputes; the
// combinational buses (the log2 unit, the multipliers) are taken at their settled
// values, their glitches left to the fit's weights. The last step is given twice, the
// operation's own and the previous operation's: the gate-level replays count an
// operation from one result strobe to the next, and where that strobe falls decides
// which of the two the interval holds (docs/energy/calibration.md).
Features operation_features(const Formats& f, const RegisterState& before, const RegisterState& after) {
  const Operands& a = before.in;
  const Operands& b = after.in;
  const Result& ra = before.r;
  const Result& rb = after.r;
  const int reg9 = f.reg9.width();
  const arith::Rom5Table& rom5 = rom5_for(f);
  const code_t h = pin19_code(f, Constants::patent);
  // Multiplexer 3 puts register 1 (aligned) on ROM 5's bus in pass 1, register 9 in pass 2.
  const std::array<code_t, 3> bus{ra.reg9_pass2, arith::mux3(f, false, b.cos, 0), rb.reg9_pass1};
  const std::array<code_t, 3> mux4{h, arith::mux4(f, false, b.n, h), h};
  std::array<code_t, 3> address{}, log2{}, mul6{};
  double rom5_reads = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    address[i] = rom5_address(f, bus[i]);
    log2[i] = rom5.log2(bus[i]);
    mul6[i] = arith::mul6(f, log2[i], mux4[i]);
    if (i > 0 && address[i] != address[i - 1]) rom5_reads += 1;
  }
  const std::array<code_t, 3> mul39{ra.norm39, arith::mul39(f, ra.reg9_pass2, rb.rom38_k),
                                    arith::mul39(f, rb.reg9_pass1, rb.rom38_k)};
  double rgb = 0, mul_rgb = 0, rgb_activity = 0;
  for (int ch = 0; ch < 3; ++ch) {
    rgb += toggles(a.rgb[ch], b.rgb[ch], f.rgb.width());
    const std::array<code_t, 3> products{ra.out[ch], arith::mul_rgb(f, mul39[1], b.rgb[ch]),
                                         arith::mul_rgb(f, mul39[2], b.rgb[ch])};
    mul_rgb += sequence_toggles(products, f.out.width());
    rgb_activity += activity(mul39[0], a.rgb[ch], mul39[1], b.rgb[ch], f.norm.width(), f.rgb.width()) +
                    activity(mul39[1], b.rgb[ch], mul39[2], b.rgb[ch], f.norm.width(), f.rgb.width());
  }
  double mul6_activity = 0;
  for (std::size_t i = 1; i < 3; ++i)
    mul6_activity += activity(log2[i - 1], mux4[i - 1], log2[i], mux4[i], f.log2.width(), f.mux4.width());
  const double mul39_activity =
      activity(ra.reg9_pass2, ra.rom38_k, ra.reg9_pass2, rb.rom38_k, reg9, f.rom38.width()) +
      activity(ra.reg9_pass2, rb.rom38_k, rb.reg9_pass1, rb.rom38_k, reg9, f.rom38.width());
  const std::array<double, 9> end = end_toggles(f, rom5, h, b, rb);
  const std::array<double, 9> prev_end = end_toggles(f, rom5, h, a, ra);
  const std::array<double, 4> ret = return_toggles(f, rom5, h, b, rb);
  const std::array<double, 4> prev_ret = return_toggles(f, rom5, h, a, ra);
  // Fig. 2 between operations: register 1 and register 2 on multiplexers 3 and 4.
  const code_t bus_a = arith::mux3(f, false, a.cos, 0), n_a = arith::mux4(f, false, a.n, h);
  const code_t log_a = rom5.log2(bus_a);
  return Features{
      1.0,
      toggles(a.cos, b.cos, f.cos.width()),
      toggles(a.n, b.n, f.n.width()),
      a.n != b.n ? 1.0 : 0.0,
      (a.n != b.n || a.rgb != b.rgb) ? 1.0 : 0.0,
      rgb,
      sequence_toggles(mux4, f.mux4.width()),
      toggles(ra.reg9_pass2, rb.reg9_pass1, reg9),
      rom5_reads,
      sequence_toggles(log2, f.log2.width()),
      sequence_toggles(mul6, reg9),
      sequence_toggles(mul39, f.norm.width()),
      mul_rgb,
      end[0], end[1], end[2], end[3], end[4], end[5],
      prev_end[0], prev_end[1], prev_end[2], prev_end[3], prev_end[4], prev_end[5],
      mul6_activity, mul39_activity, rgb_activity,
      end[6], end[7], end[8],
      prev_end[6], prev_end[7], prev_end[8],
      rom5_address(f, bus_a) != address[1] ? 1.0 : 0.0,
      toggles(log_a, log2[1], f.log2.width()),
      toggles(arith::mul6(f, log_a, n_a), mul6[1], reg9),
      activity(log_a, n_a, log2[1], mux4[1], f.log2.width(), f.mux4.width()),
      ret[0], ret[1], ret[2], ret[3],
      prev_ret[0], prev_ret[1], prev_ret[2], prev_ret[3],
      ones(rb.norm39, f.norm.width()),
      ones(rb.out[0], f.out.width()) + ones(rb.out[1], f.out.width()) + ones(rb.out[2], f.out.width()),
  };
}

}  // namespace specular::energy
