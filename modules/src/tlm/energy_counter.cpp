#include "specular/tlm/energy_counter.h"

#include <cmath>
#include <cstring>

namespace specular {

SpecularEnergyCounter::SpecularEnergyCounter(sc_core::sc_module_name name, const SpecularTarget& ip)
    : sc_module(name), socket("socket"), ip_(ip) {
  socket.register_b_transport(this, &SpecularEnergyCounter::b_transport);
}

void SpecularEnergyCounter::b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
  const std::uint64_t address = tx.get_address();
  if (address >= energy_counter::size || address % 4 != 0)
    return tx.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
  if (tx.get_data_length() != 4) return tx.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
  if (tx.get_command() == tlm::TLM_IGNORE_COMMAND) return tx.set_response_status(tlm::TLM_OK_RESPONSE);
  if (tx.get_command() != tlm::TLM_READ_COMMAND) return tx.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
  std::uint32_t word = 0;
  if (address == energy_counter::energy_pj_lo || address == energy_counter::operations_lo) {
    const energy::EnergyTally t = ip_.energy(sc_core::sc_time_stamp() + delay);
    const std::uint64_t value = address == energy_counter::energy_pj_lo
                                    ? static_cast<std::uint64_t>(std::llround(t.total_pj()))
                                    : t.operations;
    word = static_cast<std::uint32_t>(value);
    (address == energy_counter::energy_pj_lo ? energy_hi_ : operations_hi_) = static_cast<std::uint32_t>(value >> 32);
  } else {
    word = address == energy_counter::energy_pj_hi ? energy_hi_ : operations_hi_;
  }
  std::memcpy(tx.get_data_ptr(), &word, 4);
  tx.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace specular
