#include "specular/datapath/multiplexer3.h"

#include "specular/arith.h"

namespace specular {

Multiplexer3::Multiplexer3(sc_core::sc_module_name name, const Formats& formats)
    : sc_module(name), formats_(formats) {
  SPECULAR_HAS_PROCESS(Multiplexer3);
  SC_METHOD(evaluate);
  sensitive << reg1 << reg9 << select36;
}

void Multiplexer3::evaluate() {
  address.write(arith::mux3(formats_, select36.read(), reg1.read(), reg9.read()));
}

}  // namespace specular
