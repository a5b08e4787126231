#include "specular/variants/one_pass.h"

#include <stdexcept>
#include <string>

namespace specular {
namespace variants {
namespace {

/// The config itself, or std::invalid_argument naming its first width that is not the
/// default: the tops are built at the default widths only.
const Config& default_widths_only(const Config& config, const char* variant) {
  const Widths defaults{};
  for (const WidthField& field : width_fields())
    if (config.widths.*field.member != defaults.*field.member)
      throw std::invalid_argument(std::string("variant ") + variant + ": width " + field.name + " = " +
                                  std::to_string(config.widths.*field.member) +
                                  " is not built; only the default widths (" + field.name + " = " +
                                  std::to_string(defaults.*field.member) + ") are");
  return config;
}

/// Operands on the input buses at the default widths (the tail's multipliers rely on it).
void check_operands(const Operands& in) {
  const auto check = [](code_t code, code_t max, const char* what) {
    if (code < 0 || code > max)
      throw std::out_of_range(std::string("OnePass::run: ") + what + " code " + std::to_string(code) +
                              " is outside its bus (codes 0 to " + std::to_string(max) + ")");
  };
  const DefaultFormats f;
  check(in.cos, f.cos.max_code(), "register 1 (cos)");
  check(in.n, f.n.max_code(), "register 2 (n)");
  for (const code_t intensity : in.rgb) check(intensity, f.rgb.max_code(), "intensity");
}

}  // namespace

OnePass::OnePass(const Config& config, bool pipelined)
    : core_(default_widths_only(config, pipelined ? "one_pass_pipelined" : "one_pass")),
      pipelined_(pipelined) {}

VariantResult OnePass::run(const Operands& in) const {
  check_operands(in);
  const DefaultFormats f;
  const Saturation saturation = core_.config().saturation;
  // Pass 1 on the first ROM 5: a − n·log2 cos λ. Pass 2 on the second: a − h·log2(pass 1).
  const code_t pass1 = arith::pass(f, core_.rom5(), saturation, core_.pin19(), core_.pin20(), false,
                                   in.cos, 0, in.n);
  const code_t pass2 = arith::pass(f, core_.rom5(), saturation, core_.pin19(), core_.pin20(), true,
                                   in.cos, pass1, in.n);
  // The device's tail: ROM 38's K(n) × pass 2 (multiplier 39), × R, G, B (13–15).
  VariantResult result;
  result.lobe = arith::mul39(f, pass2, core_.rom38().k(in.n));
  for (int ch = 0; ch < 3; ++ch) result.out[ch] = arith::mul_rgb(f, result.lobe, in.rgb[ch]);
  return result;
}

}  // namespace variants
}  // namespace specular
