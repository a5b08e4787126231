#include "specular/datapath/register.h"

namespace specular {

Register::Register(sc_core::sc_module_name name, code_t power_on_value)
    : sc_module(name), power_on_value_(power_on_value) {
  SPECULAR_HAS_PROCESS(Register);
  SC_METHOD(capture);
  sensitive << load.pos();
  dont_initialize();
  q.initialize(power_on_value_);
}

void Register::capture() { q.write(d.read()); }

}  // namespace specular
