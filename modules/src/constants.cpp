#include "specular/constants.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace specular {

namespace {
// Frozen from `specular_constants` (tools/study/constants_search.cpp; table in
// docs/study.md §5): the branch and bound's global optimum of max_x |s·A − 2^−x| over
// the codes pins 20 (2^−22 steps) and 19 (2^−F steps) hold, with the peak exact.
//   minimax-half: h = ½ kept, a = 4819202·2^−22 = 1.148987293, error 0.073369204.
//   minimax: F = 8 (the fewest bits within 1 % of the best any F ≤ 16 reaches),
//            h = 41/256 = 0.16015625, a = 1564586·2^−22 = 0.373026371, error 0.039773968.
// tests/test_constants.cpp recomputes each error in double on a dense grid.
constexpr ConstantValues patent{code_t{1}, 0, code_t{1}, 1, 0.125};
constexpr ConstantValues minimax_half{code_t{4819202}, 22, code_t{1}, 1, 0.073369204};
constexpr ConstantValues minimax{code_t{1564586}, 22, code_t{41}, 8, 0.039773968};

code_t on_bus(code_t code, int code_frac_bits, const FixedFormat& bus, const char* width,
              Constants policy) {
  if (bus.frac_bits < code_frac_bits)
    throw std::invalid_argument(std::string("constants '") + to_string(policy) + "' need " + width +
                                " >= " + std::to_string(code_frac_bits) + " (got " +
                                std::to_string(bus.frac_bits) + ")");
  return code << (bus.frac_bits - code_frac_bits);
}
}  // namespace

double ConstantValues::a() const { return std::ldexp(static_cast<double>(a_code), -a_frac_bits); }
double ConstantValues::h() const { return std::ldexp(static_cast<double>(h_code), -h_frac_bits); }
double ConstantValues::s() const { return 1.0 / (a() - h() * std::log2(a())); }

const ConstantValues& constant_values(Constants policy) {
  switch (policy) {
    case Constants::patent: return patent;
    case Constants::minimax_half: return minimax_half;
    case Constants::minimax: return minimax;
  }
  throw std::invalid_argument("unknown constants policy");
}

code_t pin19_code(const Formats& f, Constants policy) {
  const ConstantValues& c = constant_values(policy);
  return on_bus(c.h_code, c.h_frac_bits, f.mux4, "pin19_frac_bits", policy);
}

code_t pin20_code(const Formats& f, Constants policy) {
  const ConstantValues& c = constant_values(policy);
  return on_bus(c.a_code, c.a_frac_bits, f.reg9, "reg9_frac_bits", policy);
}

}  // namespace specular
