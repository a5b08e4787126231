// The example SoC platform (docs/integration.md): a processor-like initiator, a
// generic bus, a RAM and the specular IP, wired as a third-party virtual platform
// would wire any TLM-2.0 peripheral.
//
//   cpu.bus → bus ─┬─ 0x0000_0000 RAM (the results the software stores)
//                  └─ 0x1000_0000 specular IP (docs/tlm.md register map)
//   ip.done_irq → irq line → cpu.irq (wait for interrupt); ip.on_done_irq → a counter
//
// The CPU runs a driver loop in one SC_THREAD under a tlm_utils::tlm_quantumkeeper.
// Its loads and stores are what a 64-bit core issues: 1, 2, 4 and 8 bytes, streaming
// width 0, no byte enables. Every other operation goes through SpecularDriver's
// burst path instead. Each result is checked against Core, computed here.
//
// Strict (--strict): the CPU's memory interface is riscv-vp's: it passes its quantum
// keeper's local time as `delay`, asserts after b_transport that the delay did not
// shrink, and sets the keeper to it; the assert is on in every build type (it aborts,
// as assert() does). Every access goes through it, the bursts included. The pin target
// keeps the delay by default (PinDelay::keep, as such a platform needs,
// docs/integration.md §6); --pin-delay consume shows the strict CPU refusing the other.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "bus.h"
#include "specular/specular.h"
#ifdef SOC_PLATFORM_HAS_RTL
#include "specular/twin/axi_target.h"
#include "specular/twin/rtl_sync_target.h"
#include "specular/twin/rtl_target.h"
#endif

namespace soc {

constexpr std::uint64_t ram_base = 0x00000000;
constexpr std::size_t max_operations = 100000;  ///< soc_platform --operations' limit
/// 12 bytes of results per operation: room for max_operations (it was 64 KiB, which
/// made a run of more than 5461 operations fail with an address error).
constexpr std::uint64_t ram_bytes = 0x200000;
static_assert(12 * max_operations <= ram_bytes, "the RAM holds every operation's results");
constexpr std::uint64_t ip_base = 0x10000000;

enum class Target { lt, pin, rtl, rtl_sync, axi };

/// A small processor-like initiator: loads and stores over its bus socket, a wait
/// for interrupt on `irq`, and the program in program().
class Cpu : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<Cpu, 32> bus{"bus"};
  sc_core::sc_in<bool> irq{"irq"};

  Cpu(sc_core::sc_module_name name, std::size_t operations, bool strict)
      : sc_module(name), operations_(operations), strict_(strict), driver_(bus, ip_base, keeper_) {
    SPECULAR_HAS_PROCESS(Cpu);
    // A 1 µs quantum, as riscv-vp and the Accellera LT examples use.
    tlm_utils::tlm_quantumkeeper::set_global_quantum(sc_core::sc_time(1, sc_core::SC_US));
    keeper_.reset();
    SC_THREAD(program);
  }

  std::size_t operations_done = 0;
  std::size_t matches = 0;
  std::string failure;  ///< the first thing that went wrong, empty if nothing did

 private:
  // ---- the core's memory instructions (little-endian host: byte k of a word is
  // bits 8k+7:8k, as on RISC-V) ----
  void access(tlm::tlm_command command, std::uint64_t address, void* data, unsigned length) {
    tx_.set_command(command);
    tx_.set_address(address);
    tx_.set_data_ptr(static_cast<unsigned char*>(data));
    tx_.set_data_length(length);
    tx_.set_streaming_width(0);  // as riscv-vp leaves it
    tx_.set_byte_enable_ptr(nullptr);
    tx_.set_byte_enable_length(0);
    tx_.set_dmi_allowed(false);
    tx_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_core::sc_time local = keeper_.get_local_time();
    bus->b_transport(tx_, local);
    if (strict_ && local < keeper_.get_local_time()) {
      // riscv-vp: assert(delay >= quantum_keeper.get_local_time()), kept on in Release.
      std::cerr << "soc_platform: strict initiator: the delay shrank: " << keeper_.get_local_time()
                << " passed to b_transport, " << local << " returned ("
                << (command == tlm::TLM_READ_COMMAND ? "load" : "store") << " of " << length
                << " bytes at 0x" << std::hex << address << std::dec << ")" << std::endl;
      std::abort();
    }
    keeper_.set(local);
    if (keeper_.need_sync()) keeper_.sync();
    if (!tx_.is_response_ok() && failure.empty()) {
      std::ostringstream s;
      s << (command == tlm::TLM_READ_COMMAND ? "load" : "store") << " of " << length
        << " bytes at 0x" << std::hex << address << " failed: " << tx_.get_response_string();
      failure = s.str();
    }
  }
  template <typename T>
  T load(std::uint64_t address) {
    T value{};
    access(tlm::TLM_READ_COMMAND, address, &value, sizeof value);
    return value;
  }
  template <typename T>
  void store(std::uint64_t address, T value) {
    access(tlm::TLM_WRITE_COMMAND, address, &value, sizeof value);
  }
  static std::uint64_t reg(specular::Reg r) { return ip_base + specular::offset_of(r); }
  /// Two registers in one 64-bit store: `low` at the doubleword's offset, `high` 4 above.
  static std::uint64_t doubleword(specular::code_t low, specular::code_t high) {
    return static_cast<std::uint64_t>(high) << 32 | static_cast<std::uint32_t>(low);
  }

  /// wfi: let simulated time catch up with the core, then sleep until done_irq is high.
  void wait_for_interrupt() {
    keeper_.sync();
    while (!irq.read()) wait(irq.posedge_event());
  }

  void check(bool ok, const std::string& what) {
    if (!ok && failure.empty()) failure = what;
  }

  specular::Operands next_operands() {  // a fixed pseudo-random sequence (LCG)
    const auto draw = [this](std::uint32_t range) {
      seed_ = seed_ * 1664525u + 1013904223u;
      return static_cast<std::uint32_t>((static_cast<std::uint64_t>(seed_ >> 8) * range) >> 24);
    };
    specular::Operands in;
    in.cos = draw(65537);
    in.n = 1 + draw(1000);
    in.rgb = {draw(256), draw(256), draw(256)};
    return in;
  }

  void program() {
    using specular::Reg;
    // Probe: the ID word, the minor version as a half-word, both as one doubleword,
    // STATUS as a byte (lw, lhu, ld, lbu).
    check(load<std::uint32_t>(reg(Reg::id)) == specular::device_id, "ID");
    check(load<std::uint16_t>(reg(Reg::version)) == (specular::map_version & 0xFFFF), "VERSION");
    const auto id_version = load<std::uint64_t>(reg(Reg::id));
    check(id_version == (std::uint64_t{specular::map_version} << 32 | specular::device_id),
          "ID and VERSION as one doubleword");
    check(load<std::uint8_t>(reg(Reg::status)) == 0, "STATUS idle");

    const specular::Core core;  // the reference for each result
    for (std::size_t i = 0; i < operations_ && failure.empty(); ++i) {
      const specular::Operands in = next_operands();
      std::uint32_t out[3];
      if (i % 2 == 0) {  // register by register, with every access width
        store<std::uint64_t>(reg(Reg::cos), doubleword(in.cos, in.n));  // COS and N: sd
        store<std::uint64_t>(reg(Reg::r), doubleword(in.rgb[0], in.rgb[1]));  // R and G: sd
        store<std::uint8_t>(reg(Reg::b), static_cast<std::uint8_t>(in.rgb[2]));  // B: sb
        store<std::uint32_t>(reg(Reg::control), specular::control_bits::start);
        wait_for_interrupt();
        const auto rg = load<std::uint64_t>(reg(Reg::out_r));
        out[0] = static_cast<std::uint32_t>(rg);
        out[1] = static_cast<std::uint32_t>(rg >> 32);
        out[2] = load<std::uint32_t>(reg(Reg::out_b));
      } else if (strict_) {  // the same bursts, through the strict memory interface
        const auto word = [](specular::code_t code) { return static_cast<std::uint32_t>(code); };
        std::uint32_t operands[6] = {word(in.cos),    word(in.n),      word(in.rgb[0]),
                                     word(in.rgb[1]), word(in.rgb[2]), specular::control_bits::start};
        access(tlm::TLM_WRITE_COMMAND, reg(Reg::operands), operands, sizeof operands);
        wait_for_interrupt();
        access(tlm::TLM_READ_COMMAND, reg(Reg::results), out, sizeof out);
      } else {  // the driver's burst path (OPERANDS, RESULTS)
        try {
          const auto result = driver_.compute_burst(in);
          for (int ch = 0; ch < 3; ++ch) out[ch] = static_cast<std::uint32_t>(result[ch]);
        } catch (const specular::TransportError& e) {
          failure = e.what();
          break;
        }
        wait_for_interrupt();
      }
      store<std::uint8_t>(reg(Reg::status), specular::status_bits::done);  // acknowledge: sb
      for (int ch = 0; ch < 3; ++ch) store<std::uint32_t>(ram_base + 12 * i + 4 * ch, out[ch]);
      ++operations_done;
    }
    // Read the results back from RAM and check them against Core.
    seed_ = 1;
    for (std::size_t i = 0; i < operations_done; ++i) {
      const specular::Result expected = core.run(next_operands());
      bool equal = true;
      for (int ch = 0; ch < 3; ++ch)
        equal = equal && static_cast<std::int32_t>(load<std::uint32_t>(ram_base + 12 * i + 4 * ch)) ==
                             expected.out[ch];
      matches += equal;
    }
    keeper_.sync();
    sc_core::sc_stop();  // the pin target's clock would run on forever otherwise
  }

  std::size_t operations_;
  bool strict_;
  std::uint32_t seed_ = 1;
  tlm_utils::tlm_quantumkeeper keeper_;
  specular::SpecularDriver driver_;
  tlm::tlm_generic_payload tx_;
};

/// The whole platform; `target` picks the IP's implementation.
class Platform : public sc_core::sc_module {
 public:
  Platform(sc_core::sc_module_name name, Target target, std::size_t operations,
           bool strict = false, specular::PinDelay pin_delay = specular::PinTargetSettings{}.delay)
      : sc_module(name),
        cpu("cpu", operations, strict),
        bus("bus", {{ram_base, ram_bytes, "to_ram"}, {ip_base, specular::map_size, "to_ip"}}),
        ram("ram", ram_bytes),
        ip(make_ip(target, pin_delay)) {
    cpu.bus.bind(bus.socket);
    bus.output(0).bind(ram.socket);
    bus.output(1).bind(ip->socket);
    ip->done_irq(irq_line);
    cpu.irq(irq_line);
    // An interrupt controller that takes a call per edge binds here instead.
    ip->on_done_irq([this](bool level) { interrupts += level; });
  }

  static bool has(Target target) {
#ifdef SOC_PLATFORM_HAS_RTL
    (void)target;
    return true;
#else
    return target == Target::lt || target == Target::pin;
#endif
  }

  Cpu cpu;
  Bus bus;
  Ram ram;
  std::unique_ptr<specular::SpecularTarget> ip;
  sc_core::sc_signal<bool> irq_line{"irq_line"};
  std::size_t interrupts = 0;  ///< rising edges of done_irq, by callback

 private:
  static std::unique_ptr<specular::SpecularTarget> make_ip(Target target, specular::PinDelay pin_delay) {
    switch (target) {
      case Target::lt: return std::make_unique<specular::SpecularLtTarget>("ip");
      case Target::pin: {
        // The delay policy is part of the target's settings (a strict initiator refuses
        // a delay that shrinks: keep, the default, never shrinks it).
        specular::PinTargetSettings settings;
        settings.delay = pin_delay;
        return std::make_unique<specular::SpecularPinTarget>("ip", specular::Config{}, settings);
      }
#ifdef SOC_PLATFORM_HAS_RTL
      case Target::rtl: return std::make_unique<specular::SpecularRtlTarget>("ip");
      case Target::rtl_sync: return std::make_unique<specular::SpecularRtlSyncTarget>("ip");
      case Target::axi: return std::make_unique<specular::SpecularAxiTarget>("ip");
#else
      case Target::rtl:
      case Target::rtl_sync:
      case Target::axi: break;
#endif
    }
    throw std::invalid_argument("this build of soc_platform has no rtl, rtl-sync or axi target");
  }
};

}  // namespace soc
