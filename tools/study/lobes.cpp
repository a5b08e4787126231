#include "lobes.h"

#include <algorithm>
#include <cmath>

namespace specular {
namespace study {

double schlick(double t, unsigned n) {
  return t / (n - n * t + t);  // the denominator n·(1 − t) + t ≥ 1 on [0, 1]
}

double us5739820(double t, unsigned n) {
  const double base = std::max(0.0, 1.0 - n * (1.0 - t) / 4.0);
  const double square = base * base;
  return square * square;
}

double formula_zero_crossing(unsigned n) { return std::exp2(-3.0 / n); }

std::vector<double> device_table(const Core& core, unsigned n, DeviceValue value) {
  const Formats& f = core.formats();
  std::vector<double> table(static_cast<std::size_t>(f.cos.one()) + 1);
  Operands in;
  in.n = n;
  for (code_t code = 0; code <= f.cos.one(); ++code) {
    in.cos = code;
    const Result r = core.run(in);
    table[static_cast<std::size_t>(code)] = value == DeviceValue::approx
                                                ? f.reg9.to_real(r.reg9_pass2)
                                                : f.norm.to_real(r.norm39);
  }
  return table;
}

double cos_of_code(const Core& core, code_t code) { return core.formats().cos.to_real(code); }

std::string device_label(Saturation saturation) {
  return std::string("device_") + to_string(saturation);
}

}  // namespace study
}  // namespace specular
