#include "specular/datapath/multiplier_rgb.h"

#include "specular/arith.h"

namespace specular {

MultiplierRgb::MultiplierRgb(sc_core::sc_module_name name, const Formats& formats)
    : sc_module(name), formats_(formats) {
  SPECULAR_HAS_PROCESS(MultiplierRgb);
  SC_METHOD(evaluate);
  sensitive << norm << intensity;
}

void MultiplierRgb::evaluate() {
  out.write(arith::mul_rgb(formats_, norm.read(), intensity.read()));
}

}  // namespace specular
