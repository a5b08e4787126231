#include "specular/datapath/multiplexer4.h"

#include "specular/arith.h"

namespace specular {

Multiplexer4::Multiplexer4(sc_core::sc_module_name name, const Formats& formats)
    : sc_module(name), formats_(formats) {
  SPECULAR_HAS_PROCESS(Multiplexer4);
  SC_METHOD(evaluate);
  sensitive << reg2 << h19 << select36;
}

void Multiplexer4::evaluate() {
  operand.write(arith::mux4(formats_, select36.read(), reg2.read(), h19.read()));
}

}  // namespace specular
