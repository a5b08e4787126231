/// \file
/// `rtl`: the TLM target computed by the RTL twin, clocked inside b_transport.
#pragma once

#include <memory>

#include "specular/core.h"
#include "specular/tlm/target.h"

namespace specular {

class RtlCycleModel;

/// The `rtl` target: SpecularTarget's register file computed by the RTL twin, clocked
/// inside b_transport.
///
/// The same register file as `lt` and `pin` (SpecularTarget), computed by the
/// verilated RTL (RtlCycleModel: plain C++, no SystemC process): each START or
/// BATCH_COS write clocks the twin edge by edge, inside b_transport, as the pin harness
/// would, and annotates the clock periods the twin took from the first start to the
/// last rising edge of 35 (2.5 for one operation, 2 more per streamed one). A virtual
/// platform gets the RTL's bits and cycle count at TLM speed: it never waits, so
/// initiators may run ahead under a tlm_quantumkeeper. The twin is reset at
/// construction (pin 29 for one period, not annotated). Widths other than the two the
/// RTL was verilated at are refused with std::invalid_argument.
class SpecularRtlTarget : public SpecularTarget {
 public:
  /// A target over the RTL twin verilated for `config`; `clock_period` scales the
  /// annotated latency. Throws std::invalid_argument for widths the RTL was not verilated at.
  explicit SpecularRtlTarget(sc_core::sc_module_name name, const Config& config = Config{},
                             const sc_core::sc_time& clock_period = sc_core::sc_time(10, sc_core::SC_NS));
  ~SpecularRtlTarget() override;

 private:
  void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
               std::uint32_t* out, Result& last, sc_core::sc_time& delay) override;

  std::unique_ptr<RtlCycleModel> rtl_;
  std::vector<Operands> batch_;
  std::vector<Result> results_;
};

}  // namespace specular
