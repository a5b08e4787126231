#include "specular/core.h"

#include <stdexcept>
#include <string>

namespace specular {

namespace {
bool same(const FixedFormat& a, const FixedFormat& b) {
  return a.is_signed == b.is_signed && a.int_bits == b.int_bits && a.frac_bits == b.frac_bits;
}
}  // namespace

// Every constant the core's hot path reads from DefaultFormats, compared with the
// run-time formats: only then may run() use the constants.
bool has_default_formats(const Formats& f) {
  using D = DefaultFormats;
  return same(f.cos, D::cos) && same(f.n, D::n) && same(f.rgb, D::rgb) && same(f.mux4, D::mux4) &&
         same(f.log2, D::log2) && same(f.reg9, D::reg9) && same(f.rom38, D::rom38) &&
         same(f.norm, D::norm) && same(f.out, D::out) &&
         f.widths.rom5_addr_bits == D::widths.rom5_addr_bits;
}

Core::Core(const Config& config)
    : config_(config),
      formats_(config.widths),
      cos_bits_(formats_.cos.width()),
      n_bits_(formats_.n.width()),
      rgb_bits_(formats_.rgb.width()),
      pin19_(pin19_code(formats_, config.constants)),
      pin20_(pin20_code(formats_, config.constants)),
      rom5_(formats_),
      rom38_(formats_, config),
      default_formats_(has_default_formats(formats_)) {}

void Core::refuse(const Operands& in) const {
  const auto check = [](code_t code, const FixedFormat& format, const char* what) {
    if (code < format.min_code() || code > format.max_code())
      throw std::out_of_range(std::string("Core::run: ") + what + " code " + std::to_string(code) +
                              " is outside its bus (" + format.name() + ": codes " +
                              std::to_string(format.min_code()) + " to " +
                              std::to_string(format.max_code()) + "); build Operands with Core::operands()");
  };
  check(in.cos, formats_.cos, "register 1 (cos)");
  check(in.n, formats_.n, "register 2 (n)");
  check(in.rgb[0], formats_.rgb, "register 10 (R)");
  check(in.rgb[1], formats_.rgb, "register 11 (G)");
  check(in.rgb[2], formats_.rgb, "register 12 (B)");
  throw std::logic_error("Core::refuse called with operands on their buses");
}

Operands Core::operands(double cos_lambda, long long n, long long r, long long g,
                        long long b) const {
  Operands in;
  in.cos = quantise_cos(formats_, cos_lambda);
  in.n = check_n(n);
  in.rgb = {check_rgb(formats_, r, "R"), check_rgb(formats_, g, "G"), check_rgb(formats_, b, "B")};
  return in;
}

}  // namespace specular
