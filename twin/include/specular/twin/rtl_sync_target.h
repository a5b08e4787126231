/// \file
/// `rtl-sync`: the TLM target computed by the synchronous variant, clocked inside
/// b_transport.
#pragma once

#include <memory>
#include <vector>

#include "specular/core.h"
#include "specular/tlm/target.h"

namespace specular {

class RtlSyncCycleModel;

/// The `rtl-sync` target: SpecularTarget's register file computed by the synchronous
/// variant's RTL, clocked inside b_transport.
///
/// The same register file as `lt`, `pin` and `rtl` (SpecularTarget), computed by the
/// verilated synchronous variant (RtlSyncCycleModel): each START or BATCH_COS write
/// clocks it inside b_transport and annotates the periods it took from the first start
/// edge to the last rising edge of 35: 2 T for one operation, 2 T more per streamed
/// one (the variant's timing table, docs/rtl.md). Reset at construction (not
/// annotated). Widths other than the defaults are refused with std::invalid_argument.
class SpecularRtlSyncTarget : public SpecularTarget {
 public:
  /// A target over the synchronous variant verilated for `config`; `clock_period` scales
  /// the annotated latency. Throws std::invalid_argument for widths other than the defaults.
  explicit SpecularRtlSyncTarget(sc_core::sc_module_name name, const Config& config = Config{},
                                 const sc_core::sc_time& clock_period = sc_core::sc_time(10, sc_core::SC_NS));
  ~SpecularRtlSyncTarget() override;

 private:
  void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
               std::uint32_t* out, Result& last, sc_core::sc_time& delay) override;

  std::unique_ptr<RtlSyncCycleModel> rtl_;
  std::vector<Operands> batch_;
  std::vector<Result> results_;
};

}  // namespace specular
