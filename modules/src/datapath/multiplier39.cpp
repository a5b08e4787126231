#include "specular/datapath/multiplier39.h"

#include "specular/arith.h"

namespace specular {

Multiplier39::Multiplier39(sc_core::sc_module_name name, const Formats& formats)
    : sc_module(name), formats_(formats) {
  SPECULAR_HAS_PROCESS(Multiplier39);
  SC_METHOD(evaluate);
  sensitive << reg9 << k;
}

void Multiplier39::evaluate() { norm.write(arith::mul39(formats_, reg9.read(), k.read())); }

}  // namespace specular
