#include "specular/real_view.h"

namespace specular {

RealView::RealView(sc_core::sc_module_name name, const FixedFormat& format)
    : sc_module(name), format_(format) {
  SPECULAR_HAS_PROCESS(RealView);
  SC_METHOD(follow);
  sensitive << code;
}

void RealView::follow() { value_ = format_.to_real(code.read()); }

void trace_bus(sc_core::sc_trace_file* file, const bus_signal& bus, const FixedFormat& format,
               const std::string& name) {
  if (format.is_signed) {
    sc_core::sc_trace(file, bus.read(), name, format.width());
  } else {
    // Same object seen as unsigned (signed/unsigned variants may alias); codes of an
    // unsigned format are never negative.
    sc_core::sc_trace(file, reinterpret_cast<const sc_dt::uint64&>(bus.read()), name,
                      format.width());
  }
}

}  // namespace specular
