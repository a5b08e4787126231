#include "specular/datapath/rom38.h"

namespace specular {

Rom38::Rom38(sc_core::sc_module_name name, const arith::Rom38Table& table)
    : sc_module(name), table_(table) {
  SPECULAR_HAS_PROCESS(Rom38);
  SC_METHOD(evaluate);
  sensitive << reg2;
}

void Rom38::evaluate() { k.write(table_.k(reg2.read())); }

}  // namespace specular
