// The bare-metal example (examples/firmware_rv32/main.c) run on the host against a TLM
// target (issue 47): main.c compiled as C99 with -DEXAMPLE_BUS (its driver's accessors
// come from here), -Dmain=example_main, and this header standing in for startup.S and
// the hart. Each access is a b_transport at the CPU's local time under a quantum keeper
// (as tests/test_firmware_driver.cpp's CPU); an error response is taken as an ISS takes
// it: the access is not done and example_trap(5 or 7, mepc, address) runs, whose return
// must be the next instruction. In the interrupt build, example_sleep_unless syncs, waits
// for done_irq's rising edge and calls example_trap with the machine external interrupt,
// as a hart with done_irq on its external interrupt would. With a PLIC (the example's
// PLIC build), done_irq's rising edge sets the source pending in a small model of a
// SiFive-layout PLIC at 0x0C00_0000 (source 1, context 0; riscv-vp's edge gateway), and
// the hart takes the interrupt only while the source is pending, enabled and above the
// threshold; a claim clears pending, a complete ends the service. The console is a string.
// Included by exactly one file of each test program: it defines the C symbols main.c
// expects of the platform.
#ifndef SPECULAR_TESTS_SUPPORT_FIRMWARE_EXAMPLE_HOST_H
#define SPECULAR_TESTS_SUPPORT_FIRMWARE_EXAMPLE_HOST_H

#include <cstdint>
#include <memory>
#include <string>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "specular/specular_driver.h"
#include "firmware_targets.h"
#include "plic_model.h"

extern "C" {
// main.c's
int example_main(void);
std::uintptr_t example_trap(std::uintptr_t mcause, std::uintptr_t mepc, std::uintptr_t mtval);
extern volatile std::uint32_t example_interrupts;
extern volatile std::uint32_t example_spurious_interrupts;
extern volatile std::uint32_t example_bus_faults;
// The platform's (startup.S on the hart)
void example_console_write(const char* text, std::size_t length);
void example_halt(void);
void example_exit(int status);
void example_interrupts_on(void);
void example_sleep_unless(volatile std::uint32_t* flag);
const specular_bus* example_platform_bus(void);
}

namespace specular {
namespace example_host {

constexpr std::uintptr_t ip_base = 0x50000000u;  // main.c's SPECULAR_BASE
constexpr std::uintptr_t machine_external_interrupt = 0x8000000Bu;
/// What mepc points at when an access faults: a 32-bit store (low bits 11), so a
/// handler that skips it returns mepc + 4.
alignas(4) inline const std::uint16_t faulting_store[2] = {0x2023u, 0x0000u};

using firmware_targets::Kind;
using firmware_targets::kind_name;

using firmware_targets::Plic;

struct Hart : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<Hart, 32> socket{"socket"};
  tlm_utils::tlm_quantumkeeper keeper;
  std::unique_ptr<SpecularTarget> target;
  std::string console;
  sc_core::sc_event rising_edge, never;
  std::size_t rising_edges = 0, edges_taken = 0, faults = 0, bad_resumes = 0, sleeps = 0;
  bool with_plic = false;
  /// The platform's memory interface syncs after each write to the IP (a remedy of
  /// docs/integration/riscv_vp.md): done_irq's edges reach the PLIC before the next
  /// instruction, instead of at the CPU's next sync (end of quantum, wfi).
  bool sync_after_writes = false;
  Plic plic;
  bool interrupts_on = false, halted = false, finished = false, gave_up = false;
  int exit_status = -1;

  Hart(sc_core::sc_module_name name, Kind kind, bool plic_wired, bool sync_writes)
      : sc_module(name), with_plic(plic_wired), sync_after_writes(sync_writes) {
    SPECULAR_HAS_PROCESS(Hart);
    target = firmware_targets::make_target("ip", kind, Config{});
    socket.bind(target->socket);
    target->on_done_irq([this](bool level) {
      if (!level) return;
      ++rising_edges;
      if (with_plic) plic.pending = true;  // the gateway's edge
      rising_edge.notify();
    });
    tlm_utils::tlm_quantumkeeper::set_global_quantum(sc_core::sc_time(1, sc_core::SC_US));
    keeper.reset();
    SC_THREAD(run);
  }

  void access(tlm::tlm_command command, std::uintptr_t address, std::uint32_t* word) {
    if (with_plic && address >= Plic::base && address < Plic::base + Plic::size) {
      plic.access(command, address - Plic::base, word, interrupts_on);
      return;
    }
    tlm::tlm_generic_payload tx;
    tx.set_command(command);
    tx.set_address(address - ip_base);
    tx.set_data_ptr(reinterpret_cast<unsigned char*>(word));
    tx.set_data_length(4);
    tx.set_streaming_width(4);
    tx.set_byte_enable_ptr(nullptr);
    tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_core::sc_time delay = keeper.get_local_time();
    socket->b_transport(tx, delay);
    keeper.set(delay);
    keeper.inc(sc_core::sc_time(2, sc_core::SC_NS));
    if (keeper.need_sync() || (sync_after_writes && command == tlm::TLM_WRITE_COMMAND)) keeper.sync();
    if (tx.is_response_ok()) return;
    ++faults;  // the ISS's exception: load or store access fault, mtval the address
    const std::uintptr_t mepc = reinterpret_cast<std::uintptr_t>(faulting_store);
    if (example_trap(command == tlm::TLM_READ_COMMAND ? 5u : 7u, mepc, address) != mepc + 4) ++bad_resumes;
  }

  void sleep_unless(volatile std::uint32_t* flag) {
    ++sleeps;
    keeper.sync();  // wfi: the hart yields, the edges scheduled so far are delivered
    std::size_t taken_here = 0;
    while (*flag == 0u) {
      const bool wanted = with_plic ? plic.interrupt() : rising_edges > edges_taken;
      if (interrupts_on && wanted) {
        edges_taken = rising_edges;
        if (++taken_here > 1000) park();  // a handler that never clears its source
        example_trap(machine_external_interrupt, reinterpret_cast<std::uintptr_t>(faulting_store), 0);
        continue;
      }
      if (sleeps > 100000) park();
      sc_core::wait(rising_edge);  // done_irq's next rising edge; none: the simulation ends
    }
  }

  void park() {  // the program cannot go on: stop, never return to it
    gave_up = true;
    sc_core::sc_stop();
    sc_core::wait(never);
  }

 private:
  void run() {
    exit_status = example_main();
    finished = true;
    sc_core::sc_stop();
  }
};

inline Hart* hart = nullptr;

inline Hart& run_example(Kind kind, bool plic_wired = false, bool sync_after_writes = false) {
  static std::unique_ptr<Hart> top;  // alive until exit, as SystemC wants
  top = std::make_unique<Hart>("hart", kind, plic_wired, sync_after_writes);
  hart = top.get();
  sc_core::sc_start();
  return *top;
}

/// What every build must show: it returned 0 with its PASS line, and its refused store
/// (N = 1001) trapped once, was skipped to the next instruction and was reported with its
/// cause by specular_check_error.
inline void expect_passed(const Hart& hart) {
  EXPECT_TRUE(hart.finished) << "the example never returned (halted: " << hart.halted << ")";
  EXPECT_EQ(hart.exit_status, 0) << hart.console;
  EXPECT_NE(hart.console.find("\nPASS: every result equal to Core\n"), std::string::npos) << hart.console;
  EXPECT_NE(hart.console.find("refusal: N = 1001 trapped (mcause 7, mtval 0x50000024) and skipped; "
                              "specular_check_error: cause 2 (N out of range), ERROR_ADDRESS 0x00000024\n"),
            std::string::npos)
      << hart.console;
  EXPECT_EQ(hart.faults, 1u);
  EXPECT_EQ(example_bus_faults, 1u);
  EXPECT_EQ(hart.bad_resumes, 0u) << "the trap handler did not skip the faulting store";
}

}  // namespace example_host
}  // namespace specular

extern "C" {
static std::uint32_t example_host_read32(void*, std::uintptr_t address) {
  std::uint32_t value = 0xDEADBEEFu;  // what a skipped load leaves: the register's old value
  specular::example_host::hart->access(tlm::TLM_READ_COMMAND, address, &value);
  return value;
}
static void example_host_write32(void*, std::uintptr_t address, std::uint32_t value) {
  specular::example_host::hart->access(tlm::TLM_WRITE_COMMAND, address, &value);
}
const specular_bus* example_platform_bus(void) {
  static const specular_bus bus = {example_host_read32, example_host_write32, nullptr, nullptr, nullptr, nullptr};
  return &bus;
}
void example_console_write(const char* text, std::size_t length) {
  specular::example_host::hart->console.append(text, length);
}
void example_halt(void) {
  specular::example_host::hart->halted = true;
  specular::example_host::hart->park();
}
void example_exit(int status) {  // the watchdog (off here) and unexpected traps
  specular::example_host::hart->exit_status = status;
  example_halt();
}
void example_interrupts_on(void) { specular::example_host::hart->interrupts_on = true; }
void example_sleep_unless(volatile std::uint32_t* flag) { specular::example_host::hart->sleep_unless(flag); }
}

#endif  // SPECULAR_TESTS_SUPPORT_FIRMWARE_EXAMPLE_HOST_H
