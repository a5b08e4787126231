#include "specular/datapath/rom5.h"

namespace specular {

Rom5::Rom5(sc_core::sc_module_name name, const arith::Rom5Table& table)
    : sc_module(name), table_(table) {
  SPECULAR_HAS_PROCESS(Rom5);
  SC_METHOD(evaluate);
  sensitive << address;
}

void Rom5::evaluate() { log2.write(table_.log2(address.read())); }

}  // namespace specular
