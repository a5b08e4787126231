// A real-valued mirror of a code bus, for waveforms only.
#pragma once

#include "specular/systemc.h"

namespace specular {

/// Follows a code bus and holds its value as a real number in a given format, so a
/// VCD shows `reg9_real = 0.7071` next to the raw code. Created only when tracing is
/// on: it costs one process activation per bus change.
class RealView : public sc_core::sc_module {
 public:
  bus_in code{"code"};
  RealView(sc_core::sc_module_name name, const FixedFormat& format);
  const double& value() const { return value_; }

 private:
  void follow();
  FixedFormat format_;
  double value_ = 0.0;
};

}  // namespace specular
