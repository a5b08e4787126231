/// \file
/// An energy counter a platform maps beside the IP, for firmware to read what the IP's
/// work has cost (issue 61, docs/energy.md): like a SoC's on-chip energy counters, but
/// reading the model's SpecularTarget::energy(). Not part of the IP: a platform's own
/// peripheral, so the IP's register map stays the RTL's.
#pragma once

#include <cstdint>

#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "specular/systemc.h"
#include "specular/tlm/target.h"

namespace specular {

/// The counter's registers, 32-bit, read-only (offsets from its base).
namespace energy_counter {
constexpr std::uint32_t energy_pj_lo = 0x0;   ///< the IP's energy so far, pJ, bits 31..0 (latches the rest)
constexpr std::uint32_t energy_pj_hi = 0x4;   ///< bits 63..32, as latched by the last ENERGY_PJ_LO read
constexpr std::uint32_t operations_lo = 0x8;  ///< operations so far, bits 31..0 (latches the rest)
constexpr std::uint32_t operations_hi = 0xC;  ///< bits 63..32, as latched by the last OPERATIONS_LO read
constexpr std::uint32_t size = 0x10;          ///< the window's bytes
}  // namespace energy_counter

/// The counter: 4-byte reads at the offsets of energy_counter, each the IP's tally at
/// the read's annotated time; a read of a _LO word latches its _HI word, so a 64-bit
/// value read low then high is consistent. Writes get TLM_COMMAND_ERROR_RESPONSE,
/// other offsets TLM_ADDRESS_ERROR_RESPONSE, other lengths TLM_BURST_ERROR_RESPONSE.
class SpecularEnergyCounter : public sc_core::sc_module {
 public:
  /// Bind a bus's initiator socket here.
  tlm_utils::simple_target_socket<SpecularEnergyCounter, 32> socket;
  /// A counter reading `ip`'s energy model.
  SpecularEnergyCounter(sc_core::sc_module_name name, const SpecularTarget& ip);

 private:
  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay);
  const SpecularTarget& ip_;
  std::uint32_t energy_hi_ = 0, operations_hi_ = 0;
};

}  // namespace specular
