#include "specular/datapath/adder8.h"

#include "specular/arith.h"

namespace specular {

Adder8::Adder8(sc_core::sc_module_name name, const Formats& formats, Saturation saturation)
    : sc_module(name), formats_(formats), saturation_(saturation) {
  SPECULAR_HAS_PROCESS(Adder8);
  SC_METHOD(evaluate);
  sensitive << a20 << inverted << carry34;
}

void Adder8::evaluate() {
  sum.write(arith::adder8(formats_, saturation_, a20.read(), inverted.read(), carry34.read()));
}

}  // namespace specular
