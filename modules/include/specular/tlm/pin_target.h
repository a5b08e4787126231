// `pin`: the TLM target as a transactor in front of the pin-level netlist.
#pragma once

#include <vector>

#include "specular/pin_harness.h"
#include "specular/tlm/target.h"

namespace specular {

/// Drives the device of Fig. 1 through PinHarness, as a TLM-to-pin bridge does
/// (compare Xilinx libsystemctlm-soc's tlm2apb-bridge): b_transport first waits out
/// the initiator's annotated delay, then drives pins 17–33 and waits on the clock
/// (pin 28) until pin 35 rises. Cycle-accurate; call it from an SC_THREAD. START
/// begins at the next rising clock edge at least a quarter period away (the
/// harness's protocol); a batch streams one operation every 2 periods.
/// If pin 29 was never pulsed since power-on, the first operation first resets the
/// control unit (one clock period), as spec §3 wants before any start.
/// The pins are written from the calling initiator's thread (SystemC's one-writer
/// rule): let one initiator thread run operations.
class SpecularPinTarget : public SpecularTarget {
 public:
  SpecularPinTarget(sc_core::sc_module_name name, const Config& config = Config{},
                    const sc_core::sc_time& clock_period = sc_core::sc_time(10, sc_core::SC_NS),
                    bool real_views = false);

  PinHarness harness;

 private:
  void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
               std::uint32_t* out, Result& last, sc_core::sc_time& delay) override;

  void on_reset();  // pin 29 fell: the control unit has seen a reset

  bool reset_seen_ = false;
  std::vector<Operands> operands_;
  std::vector<Result> results_;
};

}  // namespace specular
