#include "specular/real_view.h"

namespace specular {

RealView::RealView(sc_core::sc_module_name name, const FixedFormat& format)
    : sc_module(name), format_(format) {
  SPECULAR_HAS_PROCESS(RealView);
  SC_METHOD(follow);
  sensitive << code;
}

void RealView::follow() { value_ = format_.to_real(code.read()); }

}  // namespace specular
