#include "specular/energy/operation_features.h"

#include <cstdint>

namespace specular::energy {

const std::array<const char*, feature_count> feature_names = {
    "one",            // every operation: the control unit's sequence and the clock
    "toggles_reg1",   // register 1 (cos)
    "toggles_reg2",   // register 2 (n): multiplier 6's operand in pass 1
    "rom38_read",     // n changed: ROM 38 reads a new word
    "toggles_rgb",    // registers 10-12
    "toggles_reg9",   // register 9: previous pass 2 -> pass 1 -> pass 2
    "toggles_rom5",   // ROM 5's address over the four values its bus holds
    "toggles_rom38",  // ROM 38's word
    "toggles_mul39",  // multiplier 39's product
    "toggles_out",    // pins 24-26
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

/// ROM 5's address for a multiplexer-3 code: the exponent (the leading one's place)
/// and the mantissa bits after it, as Rom5Table::lookup forms them; a code ≤ 0 reads
/// the table's zero entry.
SPECULAR_ENERGY_INLINE std::uint64_t rom5_address(const Formats& f, code_t bus) {
  if (bus <= 0) return 0;
  const int bits = f.widths.rom5_addr_bits;
  const arith::LeadingOne one = arith::leading_one(static_cast<std::uint64_t>(bus), 64);
  const std::uint64_t mantissa = (one.normalised << 1) >> (64 - bits);
  return (static_cast<std::uint64_t>(one.msb) << bits) | mantissa;
}

/// ROM 5's address bits that change as its bus takes `bus` in turn: after the previous
/// operation register 9 (pass 2) sits on it, then pass 1's register 1, pass 2's
/// register 9, and register 9's new value once pass 2 is latched.
SPECULAR_ENERGY_INLINE double rom5_toggles(const Formats& f, const std::array<code_t, 4>& bus) {
  const int bits = f.widths.rom5_addr_bits + 7;  // the mantissa and the exponent
  double sum = 0;
  for (std::size_t i = 1; i < bus.size(); ++i)
    sum += toggles(static_cast<code_t>(rom5_address(f, bus[i - 1])), static_cast<code_t>(rom5_address(f, bus[i])), bits);
  return sum;
}

}  // namespace

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
  // Multiplexer 3 puts register 1 (aligned) on ROM 5's bus in pass 1, register 9 in pass 2.
  const code_t pass1_bus = b.cos << (f.reg9.frac_bits - f.cos.frac_bits);
  double rgb = 0, out = 0;
  for (int ch = 0; ch < 3; ++ch) {
    rgb += toggles(a.rgb[ch], b.rgb[ch], f.rgb.width());
    out += toggles(ra.out[ch], rb.out[ch], f.out.width());
  }
  return Features{
      1.0,
      toggles(a.cos, b.cos, f.cos.width()),
      toggles(a.n, b.n, f.n.width()),
      a.n != b.n ? 1.0 : 0.0,
      rgb,
      toggles(ra.reg9_pass2, rb.reg9_pass1, reg9) + toggles(rb.reg9_pass1, rb.reg9_pass2, reg9),
      rom5_toggles(f, {ra.reg9_pass2, pass1_bus, rb.reg9_pass1, rb.reg9_pass2}),
      toggles(ra.rom38_k, rb.rom38_k, f.rom38.width()),
      toggles(ra.norm39, rb.norm39, f.norm.width()),
      out,
  };
}

}  // namespace specular::energy
