// The TLM targets a firmware test runs the C driver against (issues 35, 46, 47): lt,
// pin with PinDelay::keep (what a riscv-vp-style initiator accepts), rtl, rtl-sync, axi,
// and axi with its transactor stalling every channel at random (seeded), each built with
// the default 10 ns clock; a name for each as GoogleTest's parameter.
#ifndef SPECULAR_TESTS_SUPPORT_FIRMWARE_TARGETS_H
#define SPECULAR_TESTS_SUPPORT_FIRMWARE_TARGETS_H

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "specular/twin/axi_target.h"
#include "specular/twin/rtl_sync_target.h"
#include "specular/twin/rtl_target.h"

namespace specular {
namespace firmware_targets {

enum class Kind { lt, pin, rtl, rtl_sync, axi, axi_stalled };

/// The RTL IP behind its AXI4-Lite transactor (no batch windows: BATCH_CAPACITY 0).
inline bool is_axi(Kind kind) { return kind == Kind::axi || kind == Kind::axi_stalled; }

/// axi_stalled's seed and the chance of a low READY in a cycle (AxiTarget::stall_at_random).
constexpr std::uint32_t stall_seed = 46;
constexpr unsigned stall_percent = 30;

inline std::string target_name(Kind kind) {
  switch (kind) {
    case Kind::lt: return "lt";
    case Kind::pin: return "pin_keep";
    case Kind::rtl: return "rtl";
    case Kind::rtl_sync: return "rtl_sync";
    case Kind::axi: return "axi";
    case Kind::axi_stalled: return "axi_stalled";
  }
  return "unknown";
}

inline std::string kind_name(const testing::TestParamInfo<Kind>& info) { return target_name(info.param); }

/// How a test's CPU reaches its target: empty, its socket bound straight to the target's;
/// else called during elaboration to bind them through something between (a bus trace
/// recorder, tests/support/bus_trace_recorder.h).
using Wiring = std::function<void(tlm::tlm_initiator_socket<32>& cpu, SpecularTarget& target)>;

inline void wire(tlm::tlm_initiator_socket<32>& cpu, SpecularTarget& target, const Wiring& wiring) {
  if (wiring)
    wiring(cpu, target);
  else
    cpu.bind(target.socket);
}

inline std::unique_ptr<SpecularTarget> make_target(const char* name, Kind kind, const Config& config) {
  const sc_core::sc_time period(10, sc_core::SC_NS);
  switch (kind) {
    case Kind::lt: return std::make_unique<SpecularLtTarget>(name, config, period);
    case Kind::pin: return std::make_unique<SpecularPinTarget>(name, config, period, false, PinDelay::keep);
    case Kind::rtl: return std::make_unique<SpecularRtlTarget>(name, config, period);
    case Kind::rtl_sync: return std::make_unique<SpecularRtlSyncTarget>(name, config, period);
    case Kind::axi: return std::make_unique<SpecularAxiTarget>(name, config, period);
    case Kind::axi_stalled: {
      auto target = std::make_unique<SpecularAxiTarget>(name, config, period);
      target->stall_at_random(stall_seed, stall_percent);
      return target;
    }
  }
  return nullptr;
}

}  // namespace firmware_targets
}  // namespace specular

#endif  // SPECULAR_TESTS_SUPPORT_FIRMWARE_TARGETS_H
