// Multiplier 6 of Fig. 1 alone: log2 × (n in pass 1, ½ in pass 2), within half an
// LSB of register 9's format of the exact product.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "specular/datapath/multiplier6.h"

namespace specular {
namespace {

void settle() { sc_core::sc_start(1, sc_core::SC_NS); }

TEST(BlockMul6, ProductIsRoundedToRegister9sFormat) {
  const Formats f;
  bus_signal log2{"log2"}, operand{"operand"}, product{"product"};
  Multiplier6 mul6{"mul6", f};
  mul6.log2(log2);
  mul6.operand(operand);
  mul6.product(product);

  const double half_lsb = f.reg9.lsb() / 2;
  std::mt19937 random(6);
  std::uniform_real_distribution<double> pass1_log2(-16.0, 0.0);   // log2 cos λ
  std::uniform_real_distribution<double> pass2_log2(0.0, 14.0);    // log2 register 9
  auto check = [&](double l, double op) {
    const code_t l_code = static_cast<code_t>(std::llround(std::ldexp(l, f.log2.frac_bits)));
    const code_t op_code = static_cast<code_t>(std::llround(std::ldexp(op, f.mux4.frac_bits)));
    log2.write(l_code);
    operand.write(op_code);
    settle();
    const double exact = f.log2.to_real(l_code) * f.mux4.to_real(op_code);
    EXPECT_NEAR(f.reg9.to_real(product.read()), exact, half_lsb) << l << " × " << op;
  };
  // Pass 1: n = 1..1000, including the corner −16 × 1000 = −16 000.
  for (double n : {1.0, 2.0, 999.0, 1000.0}) {
    check(-16.0, n);
    check(-std::ldexp(1.0, -22), n);
    check(0.0, n);
  }
  for (int i = 0; i < 300; ++i)
    check(pass1_log2(random), std::uniform_int_distribution<int>(1, 1000)(random));
  // Pass 2: × ½.
  for (int i = 0; i < 300; ++i) check(pass2_log2(random), 0.5);
  check(13.99999, 0.5);
}

}  // namespace
}  // namespace specular
