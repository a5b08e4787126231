// A PLIC as the example firmware sees it (issue 47): source 1, one context (hart 0's
// machine mode: 0 by default), SiFive's register layout by default (enables 0x80 and
// threshold/claim 0x1000 bytes per context; riscv-vp's FE310_PLIC packs them, 8 and 8 on
// its hifive-vp: set enable_stride and context_stride), riscv-vp's edge gateway (a rising
// edge of done_irq sets the source pending). The hart takes the interrupt while the source
// is pending, enabled and above the threshold; a claim clears pending, a complete ends
// the service. Shared by the example's host run and its RV32 run.
#ifndef SPECULAR_TESTS_SUPPORT_PLIC_MODEL_H
#define SPECULAR_TESTS_SUPPORT_PLIC_MODEL_H

#include <cstddef>
#include <cstdint>

#include <tlm>

namespace specular {
namespace firmware_targets {

struct Plic {
  static constexpr std::uintptr_t base = 0x0C000000u, size = 0x400000u;
  static constexpr std::uint32_t source = 1u;
  std::uint32_t context = 0, enable_stride = 0x80u, context_stride = 0x1000u;  // the layout
  std::uint32_t priority = 0, enable = 0, threshold = 0;
  bool pending = false, in_service = false;
  std::size_t claims = 0, completes = 0, claims_before_interrupts_on = 0, other_accesses = 0;
  bool interrupt() const { return pending && (enable & (1u << source)) != 0u && priority > threshold; }
  void access(tlm::tlm_command command, std::uintptr_t offset, std::uint32_t* word, bool interrupts_on) {
    const bool read = command == tlm::TLM_READ_COMMAND;
    std::uint32_t* reg = nullptr;
    const std::uintptr_t enable_at = 0x2000u + enable_stride * context;
    const std::uintptr_t threshold_at = 0x200000u + context_stride * context;
    if (offset == 4u * source) reg = &priority;
    if (offset == enable_at) reg = &enable;
    if (offset == threshold_at) reg = &threshold;
    if (reg != nullptr) {
      if (read) *word = *reg; else *reg = *word;
      return;
    }
    if (offset == threshold_at + 4u && read) {  // claim
      *word = 0u;
      if (!interrupt()) return;
      pending = false;
      in_service = true;
      ++claims;
      if (!interrupts_on) ++claims_before_interrupts_on;
      *word = source;
      return;
    }
    if (offset == threshold_at + 4u && *word == source && in_service) {  // complete
      in_service = false;
      ++completes;
      return;
    }
    ++other_accesses;
    if (read) *word = 0u;
  }
};

}  // namespace firmware_targets
}  // namespace specular

#endif  // SPECULAR_TESTS_SUPPORT_PLIC_MODEL_H
