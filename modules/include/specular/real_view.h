/// \file
/// A real-valued mirror of a code bus, for waveforms only.
#pragma once

#include <string>

#include "specular/systemc.h"

namespace specular {

/// Follows a code bus and holds its value as a real number in a given format, so a
/// VCD shows `reg9_q_real = 0.7071` next to the raw code. Created only on request
/// (`specular_tb --real-views`): it costs one process activation per bus change and a
/// `%.16g` per value written, and GTKWave shows the codes as fixed point without it.
class RealView : public sc_core::sc_module {
 public:
  bus_in code{"code"};  ///< the code bus followed
  /// A view of codes in `format`; bind `code` to the bus.
  RealView(sc_core::sc_module_name name, const FixedFormat& format);
  /// The current value, format.to_real(code), traced as a double.
  const double& value() const { return value_; }

 private:
  void follow();
  FixedFormat format_;
  double value_ = 0.0;
};

/// Traces a code bus at its format's width. An unsigned format is traced as an
/// unsigned value: SystemC's signed VCD writer prints x for a code at or above
/// 2^(width-1), e.g. cos λ = 1.0 (65536) on the 17-bit U1.16 bus.
void trace_bus(sc_core::sc_trace_file* file, const bus_signal& bus, const FixedFormat& format,
               const std::string& name);

}  // namespace specular
