#include "specular/core.h"

namespace specular {

Core::Core(const Config& config)
    : config_(config),
      formats_(config.widths),
      rom5_(formats_),
      rom38_(formats_, config.normalisation) {}

Operands Core::operands(double cos_lambda, long long n, long long r, long long g,
                        long long b) const {
  Operands in;
  in.cos = quantise_cos(formats_, cos_lambda);
  in.n = check_n(n);
  in.rgb = {check_rgb(formats_, r, "R"), check_rgb(formats_, g, "G"), check_rgb(formats_, b, "B")};
  return in;
}

}  // namespace specular
