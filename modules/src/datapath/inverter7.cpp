#include "specular/datapath/inverter7.h"

#include "specular/arith.h"

namespace specular {

Inverter7::Inverter7(sc_core::sc_module_name name, const Formats& formats)
    : sc_module(name), formats_(formats) {
  SPECULAR_HAS_PROCESS(Inverter7);
  SC_METHOD(evaluate);
  sensitive << product;
}

void Inverter7::evaluate() { inverted.write(arith::inv7(formats_, product.read())); }

}  // namespace specular
