#include "specular/control/gates.h"

namespace specular {

NotGate::NotGate(sc_core::sc_module_name name) : sc_module(name) {
  SPECULAR_HAS_PROCESS(NotGate);
  SC_METHOD(evaluate);
  sensitive << a;
}
void NotGate::evaluate() { y.write(!a.read()); }

AndGate2::AndGate2(sc_core::sc_module_name name) : sc_module(name) {
  SPECULAR_HAS_PROCESS(AndGate2);
  SC_METHOD(evaluate);
  sensitive << a << b;
}
void AndGate2::evaluate() { y.write(a.read() && b.read()); }

NandGate2::NandGate2(sc_core::sc_module_name name) : sc_module(name) {
  SPECULAR_HAS_PROCESS(NandGate2);
  SC_METHOD(evaluate);
  sensitive << a << b;
}
void NandGate2::evaluate() { y.write(!(a.read() && b.read())); }

NandGate3::NandGate3(sc_core::sc_module_name name) : sc_module(name) {
  SPECULAR_HAS_PROCESS(NandGate3);
  SC_METHOD(evaluate);
  sensitive << a << b << c;
}
void NandGate3::evaluate() { y.write(!(a.read() && b.read() && c.read())); }

}  // namespace specular
