#include "specular/datapath/multiplier6.h"

#include "specular/arith.h"

namespace specular {

Multiplier6::Multiplier6(sc_core::sc_module_name name, const Formats& formats)
    : sc_module(name), formats_(formats) {
  SPECULAR_HAS_PROCESS(Multiplier6);
  SC_METHOD(evaluate);
  sensitive << log2 << operand;
}

void Multiplier6::evaluate() {
  product.write(arith::mul6(formats_, log2.read(), operand.read()));
}

}  // namespace specular
