// The verilated whole IP (rtl/ip/specular_ip_axi.v) as an AXI4-Lite master drives it,
// one transfer at a time, for the TLM `axi` target (axi_target.h). No SystemC here.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "specular/core.h"

namespace specular {

class AxiIpModel {
 public:
  /// Reset, ROMs written with the words of config.widths.
  explicit AxiIpModel(const Config& config);
  ~AxiIpModel();
  /// One write transfer (AW and W together); returns BRESP. Clocks until B.
  std::uint32_t write(std::uint32_t address, std::uint32_t data, std::uint32_t strobes);
  /// One read transfer; returns RRESP and RDATA in `data`. Clocks until R.
  std::uint32_t read(std::uint32_t address, std::uint32_t& data);
  /// The first AXI4-Lite rule the IP broke since the last call, or "".
  std::string take_violation();
  bool done_irq() const;
  /// Clock cycles since reset.
  std::uint64_t cycles() const;
  /// Every change of done_irq since the last call: (cycle count, new level).
  std::vector<std::pair<std::uint64_t, bool>> take_irq_edges();
  /// The master stalls every channel at random from now on (seeded; 0 %: never).
  void stall_at_random(std::uint32_t seed, unsigned percent);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace specular
