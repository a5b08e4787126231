/// \file
/// `axi`: the TLM target whose every access is an AXI4-Lite transfer to the verilated
/// whole IP (rtl/ip/specular_ip_axi.v), clocked inside b_transport.
#pragma once

#include <cstdint>
#include <memory>

#include "specular/core.h"
#include "specular/tlm/target.h"

namespace specular {

class AxiIpModel;

/// The `axi` target: a TLM-2.0 -> AXI4-Lite transactor over the verilated IP.
///
/// It derives from SpecularTarget for its public face (socket, done_irq, on_done_irq,
/// config(), clock_period()) so that it fits every suite's make_target; the base's C++
/// register file is not used: b_transport turns each access into AXI4-Lite transfers
/// (4 bytes: one, WSTRB 0xF; 1 and 2 bytes: one with those lanes' strobes; 8 bytes and
/// window bursts: consecutive single transfers, AXI4-Lite has no bursts), clocks the
/// model until each response and annotates the cycles x clock_period() on `delay`.
/// A payload AXI4-Lite cannot carry is refused first by `lt`'s own shape checks (the
/// RTL's STATUS then stays as it was); a write's words are vetted with the map's value
/// rules first, and a refused one is sent alone (all or nothing, as on `lt`). A
/// START's B comes after the operation, so the operation ends inside the access as on
/// `lt`. The IP is idle between accesses (no operation outlives its START's response),
/// so the time between calls needs no clocking. OKAY -> TLM_OK; DECERR ->
/// TLM_ADDRESS_ERROR_RESPONSE; SLVERR -> the response `lt` gives for the cause the RTL
/// set in STATUS (read back over AXI). done_irq follows the RTL's done_irq pin, each
/// edge at its cycle. Debug reads are AXI reads of mapped words clocked in zero
/// simulated time; debug writes are refused (0 bytes). `execute` is never called.
/// docs/rtl_ip/tlm_axi.md ("TLM axi target") lists where it differs from `lt`.
/// Widths other than the defaults are refused with std::invalid_argument (the IP is
/// verilated at the default widths only).
class SpecularAxiTarget : public SpecularTarget {
 public:
  /// A transactor over the verilated specular_ip_axi, reset at construction (not
  /// annotated); `clock_period` is the bus clock the cycles are annotated in. Throws
  /// std::invalid_argument for a Config the IP was not verilated for (widths, policies).
  explicit SpecularAxiTarget(sc_core::sc_module_name name, const Config& config = Config{},
                             const sc_core::sc_time& clock_period = sc_core::sc_time(10, sc_core::SC_NS));
  ~SpecularAxiTarget() override;

  /// Bus clock cycles clocked since construction (reset excluded).
  std::uint64_t cycles() const;
  /// From now on the transactor stalls every channel at random, seeded by `seed`:
  /// AWVALID, WVALID and ARVALID rise 0-3 cycles late, BREADY and RREADY are low in a
  /// cycle with `percent` % chance (0: never, the default; above 50 is refused with
  /// std::invalid_argument). The IP's answers must not change, only the cycles taken.
  void stall_at_random(std::uint32_t seed, unsigned percent);

 private:
  void execute(const Operands& shared, const std::uint32_t* cos, std::size_t count,
               std::uint32_t* out, Result& last, sc_core::sc_time& delay) override;
  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) override;
  unsigned int transport_dbg(tlm::tlm_generic_payload& tx) override;
  /// The whole access as AXI transfers; returns the TLM response.
  tlm::tlm_response_status access(tlm::tlm_generic_payload& tx, std::uint64_t& cycles_taken);
  /// Whether the map refuses word `index` of a write of `value` at `address` (on `row`):
  /// a hole, a read-only row, a value out of range.
  bool map_refuses(const RegisterInfo& row, std::uint64_t address, unsigned index,
                   std::uint32_t value) const;
  /// One AXI4-Lite transfer (a read fills `word`); a refusal is logged and answered with
  /// lt's response for the cause the RTL set.
  tlm::tlm_response_status transfer(const Attempt& attempt, std::uint64_t address, bool is_write,
                                    std::uint32_t& word, std::uint32_t strobes);

  /// The energy model's view of a write the RTL took: the operand registers as the
  /// RTL holds them (its merges of sub-word writes), and each START charged on them.
  void charge_write(std::uint64_t address, std::uint32_t word, std::uint32_t strobes);

  std::unique_ptr<AxiIpModel> ip_;
  /// COS, N, R, G, B as last written (their reset values at first): the energy
  /// model's operands, since the registers live in the RTL.
  struct HeldOperands {
    std::uint32_t cos_word = info(Reg::cos).reset;
    std::uint32_t n_word = info(Reg::n).reset;
    std::array<std::uint32_t, 3> rgb_words{info(Reg::r).reset, info(Reg::g).reset, info(Reg::b).reset};
  } operands_;
};

}  // namespace specular
