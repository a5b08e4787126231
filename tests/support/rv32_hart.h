// A small RV32IMC machine-mode hart with Zicsr, for running the bare-metal example's ELF
// (examples/firmware_rv32) against a TLM target (issue 47): what riscv-vp's tiny32 does
// for it, no more. RAM at 0 (32 MiB); the IP's window at 0x5000_0000 through a socket at
// the hart's local time under a quantum keeper (10 ns per instruction, 1 us quantum); a
// CLINT at 0x0200_0000 as riscv-vp's (SiFive's layout: hart 0's mtimecmp at +0x4000,
// mtime at +0xBFF8, mtime counting microseconds of simulated time, the hart's local time
// included; mtime >= mtimecmp raises the machine timer interrupt); done_irq through a PLIC
// (plic_model.h) at 0x0C00_0000, or straight to the machine external interrupt with no
// PLIC on the bus, or straight to the hart beside a PLIC that done_irq does not reach (the
// wiring the PLIC build must not hang on). An error response is a load or store access
// fault (mcause 5 or 7, mtval the address), as an ISS takes it; so is an access outside
// the map. ecall with a7 = 64 (write) and 93 (exit) is taken as riscv-vp's
// --intercept-syscalls takes it. wfi syncs and sleeps until an enabled interrupt is
// pending (the timer's at mtimecmp). Interrupts are taken in the specification's order
// (external before timer). No A, F or D extension, no privilege below M, no misaligned
// access: the example uses none.
#ifndef SPECULAR_TESTS_SUPPORT_RV32_HART_H
#define SPECULAR_TESTS_SUPPORT_RV32_HART_H

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "firmware_targets.h"
#include "plic_model.h"
#include "specular/tlm/energy_counter.h"

namespace specular {
namespace firmware_targets {

/// Where done_irq goes.
enum class IrqWiring {
  hart,             ///< straight to the machine external interrupt; no PLIC on the bus
  plic,             ///< through the PLIC (its edge gateway), whose output is the external interrupt
  hart_beside_plic  ///< straight to the hart; a PLIC on the bus with nothing on its source
};

struct Rv32Hart : sc_core::sc_module {
  static constexpr std::uint32_t ram_size = 32u << 20, ip_base = 0x50000000u, ip_size = 0x8000u;
  static constexpr std::uint32_t clint_base = 0x02000000u, clint_size = 0x10000u;
  /// The platform's energy counter (issue 61, specular/tlm/energy_counter.h).
  static constexpr std::uint32_t energy_counter_base = 0x50010000u;
  tlm_utils::simple_initiator_socket<Rv32Hart, 32> socket{"socket"};
  tlm_utils::simple_initiator_socket<Rv32Hart, 32> counter_socket{"counter_socket"};
  std::unique_ptr<SpecularEnergyCounter> counter;
  tlm_utils::tlm_quantumkeeper keeper;
  std::unique_ptr<SpecularTarget> target;
  std::vector<std::uint8_t> ram = std::vector<std::uint8_t>(ram_size);
  std::uint32_t x[32] = {}, pc = 0;
  std::uint32_t mstatus = 0, mie = 0, mtvec = 0, mepc = 0, mcause = 0, mtval = 0, mscratch = 0;
  IrqWiring irq_wiring = IrqWiring::hart;
  bool line = false, exited = false, stuck = false;
  std::uint64_t mtimecmp = ~std::uint64_t(0);  // reset value unspecified; here: never
  int exit_code = -1;
  std::string console, error;
  std::uint64_t instructions = 0, limit = 1000000;  // the example takes about 7 000
  std::size_t faults = 0, interrupts = 0, timer_interrupts = 0;
  /// The causes a refused load and store raise: the access faults (5, 7), or riscv-vp's
  /// page faults (13, 15; what the issue saw on it).
  std::uint32_t load_fault = 5u, store_fault = 7u;
  Plic plic;
  sc_core::sc_event irq_event;
  /// Instructions spent in the function at probe_entry (to its return), summed over calls.
  std::uint32_t probe_entry = ~0u, probe_return = ~0u;
  std::uint64_t probe_started = 0, probe_instructions = 0;

  /// `wiring`: how the socket reaches the target (firmware_targets.h; empty: straight).
  Rv32Hart(sc_core::sc_module_name name, Kind kind, IrqWiring irq_wiring_, const std::string& elf,
           const Wiring& wiring = {})
      : sc_module(name), irq_wiring(irq_wiring_) {
    SPECULAR_HAS_PROCESS(Rv32Hart);
    target = make_target("ip", kind, Config{});
    wire(socket, *target, wiring);
    counter = std::make_unique<SpecularEnergyCounter>("energy_counter", *target);
    counter_socket.bind(counter->socket);
    target->on_done_irq([this](bool level) {
      if (level && !line && irq_wiring == IrqWiring::plic) plic.pending = true;  // the gateway's edge
      line = level;
      irq_event.notify();
    });
    load(elf);
    tlm_utils::tlm_quantumkeeper::set_global_quantum(sc_core::sc_time(1, sc_core::SC_US));
    keeper.reset();
    SC_THREAD(run);
  }

  // ---- the ELF ----------------------------------------------------------------------
  void load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> f((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (f.size() < 52 || std::memcmp(f.data(), "\x7f" "ELF\x01\x01", 6) != 0)
      throw std::runtime_error("not a 32-bit little-endian ELF: " + path);
    auto u32 = [&](std::size_t at) { std::uint32_t v; std::memcpy(&v, &f.at(at + 3) - 3, 4); return v; };
    auto u16 = [&](std::size_t at) { return static_cast<std::uint32_t>(f.at(at) | f.at(at + 1) << 8); };
    pc = u32(24);
    const std::uint32_t phoff = u32(28), phentsize = u16(42), phnum = u16(44);
    for (std::uint32_t i = 0; i < phnum; ++i) {
      const std::size_t ph = phoff + i * phentsize;
      if (u32(ph) != 1u) continue;  // PT_LOAD
      const std::uint32_t offset = u32(ph + 4), paddr = u32(ph + 12), filesz = u32(ph + 16), memsz = u32(ph + 20);
      if (std::uint64_t(paddr) + memsz > ram_size || std::uint64_t(offset) + filesz > f.size())
        throw std::runtime_error("a segment outside RAM or the file");
      std::memcpy(&ram[paddr], &f[offset], filesz);
    }
  }

  // ---- the bus ----------------------------------------------------------------------
  /// One access of `size` bytes; false: an access fault (the trap is taken by the caller).
  bool access(bool write, std::uint32_t address, std::uint32_t size, std::uint32_t& value) {
    if (std::uint64_t(address) + size <= ram_size) {
      if (write) std::memcpy(&ram[address], &value, size);
      else {
        value = 0;
        std::memcpy(&value, &ram[address], size);
      }
      return true;
    }
    if (irq_wiring != IrqWiring::hart && address >= Plic::base && address < Plic::base + Plic::size && size == 4) {
      plic.access(write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND, address - Plic::base, &value,
                  (mstatus & 8u) != 0u);
      return true;
    }
    if (address >= clint_base && address - clint_base < clint_size && size == 4) {
      clint_access(write, address - clint_base, value);
      return true;
    }
    const bool to_counter = address >= energy_counter_base && address - energy_counter_base < energy_counter::size;
    if (!to_counter && (address < ip_base || address - ip_base >= ip_size)) return false;
    tlm::tlm_generic_payload tx;
    std::uint32_t word = write ? value : 0xDEADBEEFu;
    tx.set_command(write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND);
    tx.set_address(address - (to_counter ? energy_counter_base : ip_base));
    tx.set_data_ptr(reinterpret_cast<unsigned char*>(&word));
    tx.set_data_length(size);
    tx.set_streaming_width(size);
    tx.set_byte_enable_ptr(nullptr);
    tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_core::sc_time delay = keeper.get_local_time();
    (to_counter ? counter_socket : socket)->b_transport(tx, delay);
    keeper.set(delay);
    if (!tx.is_response_ok()) return false;
    if (!write) value = size == 4 ? word : word & ((1u << (8 * size)) - 1u);
    return true;
  }

  // ---- traps and interrupts ---------------------------------------------------------
  void trap(std::uint32_t cause, std::uint32_t value, std::uint32_t at) {
    mepc = at;
    mcause = cause;
    mtval = value;
    mstatus = (mstatus & ~0x88u) | ((mstatus & 8u) << 4);  // MPIE = MIE, MIE = 0 (MPP stays M)
    pc = mtvec & ~3u;
  }
  bool external_pending() const { return irq_wiring == IrqWiring::plic ? plic.interrupt() : line; }
  std::uint32_t mip() const { return (external_pending() ? 0x800u : 0u) | (mtime() >= mtimecmp ? 0x80u : 0u); }

  // ---- the CLINT --------------------------------------------------------------------
  /// Microseconds of simulated time at the hart's local time (riscv-vp's CLINT: 1 MHz).
  std::uint64_t mtime() const {
    return (sc_core::sc_time_stamp() + keeper.get_local_time()).value() / sc_core::sc_time(1, sc_core::SC_US).value();
  }
  /// mtimecmp's words are writable, mtime's read-only; msip and the rest read 0.
  void clint_access(bool write, std::uint32_t offset, std::uint32_t& value) {
    const std::uint64_t now = mtime();
    const std::uint64_t low = 0xFFFFFFFFull;
    switch (offset) {
      case 0x4000:
        if (write) mtimecmp = (mtimecmp & ~low) | value;
        else value = std::uint32_t(mtimecmp);
        return;
      case 0x4004:
        if (write) mtimecmp = (mtimecmp & low) | std::uint64_t(value) << 32;
        else value = std::uint32_t(mtimecmp >> 32);
        return;
      case 0xBFF8: if (!write) value = std::uint32_t(now); return;
      case 0xBFFC: if (!write) value = std::uint32_t(now >> 32); return;
      default: if (!write) value = 0u;
    }
  }
  /// Simulated time until mtime reaches mtimecmp (zero if it has).
  sc_core::sc_time until_timer() const {
    const sc_core::sc_time now = sc_core::sc_time_stamp() + keeper.get_local_time();
    const double at_us = static_cast<double>(mtimecmp);
    const sc_core::sc_time at = sc_core::sc_time(at_us, sc_core::SC_US);
    return at > now ? at - now : sc_core::SC_ZERO_TIME;
  }

  std::uint32_t& csr(std::uint32_t number, bool& ok) {
    static std::uint32_t zero;
    ok = true;
    switch (number) {
      case 0x300: return mstatus;
      case 0x304: return mie;
      case 0x305: return mtvec;
      case 0x340: return mscratch;
      case 0x341: return mepc;
      case 0x342: return mcause;
      case 0x343: return mtval;
      default: ok = false; zero = 0; return zero;
    }
  }

  // ---- execution --------------------------------------------------------------------
  static std::int32_t sext(std::uint32_t value, int bits) {
    const std::uint32_t m = 1u << (bits - 1);
    return static_cast<std::int32_t>((value ^ m) - m);
  }
  void set(std::uint32_t rd, std::uint32_t value) {
    if (rd != 0) x[rd] = value;
  }

  /// Expands a compressed instruction into its 32-bit form (the forms -march=rv32imac
  /// emits); 0 for one this hart does not take.
  static std::uint32_t expand(std::uint32_t c) {
    auto r = [&](int at) { return 8u + ((c >> at) & 7u); };  // x8..x15
    auto bit = [&](int at) { return (c >> at) & 1u; };
    const std::uint32_t op = c & 3u, f3 = (c >> 13) & 7u, rd = (c >> 7) & 31u, rs2 = (c >> 2) & 31u;
    auto i_type = [](std::uint32_t imm, std::uint32_t rs1, std::uint32_t f, std::uint32_t d, std::uint32_t o) {
      return (imm & 0xFFFu) << 20 | rs1 << 15 | f << 12 | d << 7 | o;
    };
    auto s_type = [](std::uint32_t imm, std::uint32_t s2, std::uint32_t s1, std::uint32_t f, std::uint32_t o) {
      return ((imm >> 5) & 0x7Fu) << 25 | s2 << 20 | s1 << 15 | f << 12 | (imm & 31u) << 7 | o;
    };
    auto r_type = [](std::uint32_t f7, std::uint32_t s2, std::uint32_t s1, std::uint32_t f, std::uint32_t d) {
      return f7 << 25 | s2 << 20 | s1 << 15 | f << 12 | d << 7 | 0x33u;
    };
    auto b_type = [](std::int32_t imm, std::uint32_t s1, std::uint32_t f) {
      const std::uint32_t i = static_cast<std::uint32_t>(imm);
      return ((i >> 12) & 1u) << 31 | ((i >> 5) & 0x3Fu) << 25 | s1 << 15 | f << 12 | ((i >> 1) & 15u) << 8 |
             ((i >> 11) & 1u) << 7 | 0x63u;
    };
    auto j_type = [](std::int32_t imm, std::uint32_t d) {
      const std::uint32_t i = static_cast<std::uint32_t>(imm);
      return ((i >> 20) & 1u) << 31 | ((i >> 1) & 0x3FFu) << 21 | ((i >> 11) & 1u) << 20 | ((i >> 12) & 0xFFu) << 12 |
             d << 7 | 0x6Fu;
    };
    const std::uint32_t ci_imm = bit(12) << 5 | ((c >> 2) & 31u);
    const std::int32_t cj = sext(bit(12) << 11 | bit(11) << 4 | ((c >> 9) & 3u) << 8 | bit(8) << 10 | bit(7) << 6 |
                                     bit(6) << 7 | ((c >> 3) & 7u) << 1 | bit(2) << 5, 12);
    const std::int32_t cb = sext(bit(12) << 8 | ((c >> 10) & 3u) << 3 | ((c >> 5) & 3u) << 6 | bit(2) << 5 |
                                     ((c >> 3) & 3u) << 1, 9);
    if (op == 0) {
      const std::uint32_t lw_off = ((c >> 10) & 7u) << 3 | bit(6) << 2 | bit(5) << 6;
      if (f3 == 0) {  // c.addi4spn
        const std::uint32_t imm = ((c >> 11) & 3u) << 4 | ((c >> 7) & 15u) << 6 | bit(6) << 2 | bit(5) << 3;
        return imm == 0 ? 0 : i_type(imm, 2, 0, r(2), 0x13);
      }
      if (f3 == 2) return i_type(lw_off, r(7), 2, r(2), 0x03);  // c.lw
      if (f3 == 6) return s_type(lw_off, r(2), r(7), 2, 0x23);  // c.sw
      return 0;
    }
    if (op == 1) {
      switch (f3) {
        case 0: return i_type(static_cast<std::uint32_t>(sext(ci_imm, 6)), rd, 0, rd, 0x13);  // c.addi
        case 1: return j_type(cj, 1);                                                            // c.jal
        case 2: return i_type(static_cast<std::uint32_t>(sext(ci_imm, 6)), 0, 0, rd, 0x13);   // c.li
        case 3:
          if (rd == 2) {  // c.addi16sp
            const std::uint32_t imm = bit(12) << 9 | bit(6) << 4 | bit(5) << 6 | ((c >> 3) & 3u) << 7 | bit(2) << 5;
            return i_type(static_cast<std::uint32_t>(sext(imm, 10)), 2, 0, 2, 0x13);
          }
          return static_cast<std::uint32_t>(sext(ci_imm, 6)) << 12 | rd << 7 | 0x37u;  // c.lui
        case 4: {
          const std::uint32_t d = r(7), f2 = (c >> 10) & 3u;
          if (f2 == 0) return i_type(ci_imm & 31u, d, 5, d, 0x13);                  // c.srli
          if (f2 == 1) return i_type((ci_imm & 31u) | 0x400u, d, 5, d, 0x13);       // c.srai
          if (f2 == 2) return i_type(static_cast<std::uint32_t>(sext(ci_imm, 6)), d, 7, d, 0x13);  // c.andi
          const std::uint32_t s = r(2), f = (c >> 5) & 3u;
          if (bit(12)) return 0;
          if (f == 0) return r_type(0x20, s, d, 0, d);  // c.sub
          if (f == 1) return r_type(0, s, d, 4, d);     // c.xor
          if (f == 2) return r_type(0, s, d, 6, d);     // c.or
          return r_type(0, s, d, 7, d);                 // c.and
        }
        case 5: return j_type(cj, 0);           // c.j
        case 6: return b_type(cb, r(7), 0);     // c.beqz
        default: return b_type(cb, r(7), 1);    // c.bnez
      }
    }
    if (op == 2) {
      if (f3 == 0) return i_type(ci_imm & 31u, rd, 1, rd, 0x13);  // c.slli
      if (f3 == 2) return i_type(bit(12) << 5 | ((c >> 4) & 7u) << 2 | ((c >> 2) & 3u) << 6, 2, 2, rd, 0x03);  // c.lwsp
      if (f3 == 6) return s_type(((c >> 9) & 15u) << 2 | ((c >> 7) & 3u) << 6, rs2, 2, 2, 0x23);  // c.swsp
      if (f3 == 4) {
        if (!bit(12)) return rs2 == 0 ? i_type(0, rd, 0, 0, 0x67) : r_type(0, rs2, 0, 0, rd);  // c.jr, c.mv
        if (rs2 == 0) return rd == 0 ? 0x00100073u : i_type(0, rd, 0, 1, 0x67);             // c.ebreak, c.jalr
        return r_type(0, rs2, rd, 0, rd);                                                       // c.add
      }
    }
    return 0;
  }

  /// Runs one instruction (or takes one interrupt); false when the program stopped.
  bool step() {
    if ((mstatus & 8u) && (mie & mip())) {
      if (mie & mip() & 0x800u) {  // external before timer, as the specification orders them
        ++interrupts;
        trap(0x8000000Bu, 0, pc);
      } else {
        ++timer_interrupts;
        trap(0x80000007u, 0, pc);
      }
      return true;
    }
    keeper.inc(sc_core::sc_time(10, sc_core::SC_NS));
    if (keeper.need_sync()) keeper.sync();
    if (++instructions > limit) return fail("over " + std::to_string(limit) + " instructions");
    if (pc + 4u > ram_size || (pc & 1u)) return fail("pc " + std::to_string(pc) + " outside RAM");
    if (pc == probe_entry && probe_return == ~0u) {
      probe_return = x[1];
      probe_started = instructions;
    } else if (pc == probe_return) {
      probe_instructions += instructions - probe_started;
      probe_return = ~0u;
    }
    std::uint32_t insn = 0;
    std::memcpy(&insn, &ram[pc], 4);
    std::uint32_t length = 4;
    if ((insn & 3u) != 3u) {
      const std::uint32_t wide = expand(insn & 0xFFFFu);
      if (wide == 0) return fail("compressed instruction " + std::to_string(insn & 0xFFFFu) + " not taken");
      insn = wide;
      length = 2;
    }
    return execute(insn, length);
  }

  bool fail(const std::string& what) {
    error = what;
    stuck = true;
    return false;
  }

  bool execute(std::uint32_t i, std::uint32_t length) {
    const std::uint32_t opcode = i & 0x7Fu, rd = (i >> 7) & 31u, f3 = (i >> 12) & 7u, rs1 = (i >> 15) & 31u,
                        rs2 = (i >> 20) & 31u, f7 = i >> 25;
    const std::uint32_t a = x[rs1], b = x[rs2], next = pc + length;
    const std::int32_t imm_i = sext(i >> 20, 12);
    const std::int32_t imm_s = sext((i >> 25) << 5 | ((i >> 7) & 31u), 12);
    const std::int32_t imm_b = sext(((i >> 31) << 12) | (((i >> 7) & 1u) << 11) | (((i >> 25) & 0x3Fu) << 5) |
                                        (((i >> 8) & 15u) << 1), 13);
    const std::int32_t imm_j = sext(((i >> 31) << 20) | (((i >> 12) & 0xFFu) << 12) | (((i >> 20) & 1u) << 11) |
                                        (((i >> 21) & 0x3FFu) << 1), 21);
    std::uint32_t pc_next = next;
    switch (opcode) {
      case 0x37: set(rd, i & 0xFFFFF000u); break;       // lui
      case 0x17: set(rd, pc + (i & 0xFFFFF000u)); break;  // auipc
      case 0x6F: set(rd, next); pc_next = pc + static_cast<std::uint32_t>(imm_j); break;  // jal
      case 0x67: pc_next = (a + static_cast<std::uint32_t>(imm_i)) & ~1u; set(rd, next); break;  // jalr
      case 0x63: {
        bool taken = false;
        switch (f3) {
          case 0: taken = a == b; break;
          case 1: taken = a != b; break;
          case 4: taken = static_cast<std::int32_t>(a) < static_cast<std::int32_t>(b); break;
          case 5: taken = static_cast<std::int32_t>(a) >= static_cast<std::int32_t>(b); break;
          case 6: taken = a < b; break;
          case 7: taken = a >= b; break;
          default: return fail("branch funct3");
        }
        if (taken) pc_next = pc + static_cast<std::uint32_t>(imm_b);
        break;
      }
      case 0x03: {  // loads
        const std::uint32_t address = a + static_cast<std::uint32_t>(imm_i);
        const std::uint32_t size = f3 == 0 || f3 == 4 ? 1u : f3 == 1 || f3 == 5 ? 2u : 4u;
        std::uint32_t value = 0;
        if (!access(false, address, size, value)) {
          ++faults;
          trap(load_fault, address, pc);
          return true;
        }
        if (f3 == 0) value = static_cast<std::uint32_t>(sext(value, 8));
        if (f3 == 1) value = static_cast<std::uint32_t>(sext(value, 16));
        set(rd, value);
        break;
      }
      case 0x23: {  // stores
        const std::uint32_t address = a + static_cast<std::uint32_t>(imm_s);
        std::uint32_t value = b;
        if (!access(true, address, 1u << f3, value)) {
          ++faults;
          trap(store_fault, address, pc);
          return true;
        }
        break;
      }
      case 0x13: {  // op-imm
        const std::uint32_t u = static_cast<std::uint32_t>(imm_i), shamt = rs2;
        switch (f3) {
          case 0: set(rd, a + u); break;
          case 2: set(rd, static_cast<std::int32_t>(a) < imm_i); break;
          case 3: set(rd, a < u); break;
          case 4: set(rd, a ^ u); break;
          case 6: set(rd, a | u); break;
          case 7: set(rd, a & u); break;
          case 1: set(rd, a << shamt); break;
          default: set(rd, (f7 & 0x20u) ? static_cast<std::uint32_t>(static_cast<std::int32_t>(a) >> shamt) : a >> shamt);
        }
        break;
      }
      case 0x33: {  // op, and M
        if (f7 == 1) {
          const std::int64_t sa = static_cast<std::int32_t>(a), sb = static_cast<std::int32_t>(b);
          switch (f3) {
            case 0: set(rd, a * b); break;
            case 1: set(rd, static_cast<std::uint32_t>((sa * sb) >> 32)); break;
            case 2: set(rd, static_cast<std::uint32_t>((sa * static_cast<std::int64_t>(b)) >> 32)); break;
            case 3: set(rd, static_cast<std::uint32_t>((std::uint64_t(a) * b) >> 32)); break;
            case 4: set(rd, b == 0 ? ~0u : (a == 0x80000000u && b == ~0u) ? a : static_cast<std::uint32_t>(sa / sb)); break;
            case 5: set(rd, b == 0 ? ~0u : a / b); break;
            case 6: set(rd, b == 0 ? a : (a == 0x80000000u && b == ~0u) ? 0u : static_cast<std::uint32_t>(sa % sb)); break;
            default: set(rd, b == 0 ? a : a % b);
          }
          break;
        }
        switch (f3) {
          case 0: set(rd, f7 ? a - b : a + b); break;
          case 1: set(rd, a << (b & 31u)); break;
          case 2: set(rd, static_cast<std::int32_t>(a) < static_cast<std::int32_t>(b)); break;
          case 3: set(rd, a < b); break;
          case 4: set(rd, a ^ b); break;
          case 5: set(rd, f7 ? static_cast<std::uint32_t>(static_cast<std::int32_t>(a) >> (b & 31u)) : a >> (b & 31u)); break;
          case 6: set(rd, a | b); break;
          default: set(rd, a & b);
        }
        break;
      }
      case 0x0F: break;  // fence
      case 0x73: {
        if (f3 == 0) {
          if (i == 0x00000073u) return ecall(next);
          if (i == 0x30200073u) {  // mret
            mstatus = (mstatus & ~0x88u) | ((mstatus >> 4) & 8u) | 0x80u;
            pc_next = mepc;
            break;
          }
          if (i == 0x10500073u) {  // wfi
            keeper.sync();
            while (!(mie & mip())) {
              if ((mie & 0x80u) && mtimecmp != ~std::uint64_t(0)) sc_core::wait(until_timer(), irq_event);
              else sc_core::wait(irq_event);  // nothing to wake it: the simulation ends
            }
            break;
          }
          return fail("system instruction " + std::to_string(i));
        }
        bool ok = false;
        std::uint32_t& reg = csr(i >> 20, ok);
        if (!ok) return fail("csr " + std::to_string(i >> 20));
        const std::uint32_t old = reg, src = f3 >= 5 ? rs1 : a;
        switch (f3 & 3u) {
          case 1: reg = src; break;
          case 2: if (rs1 != 0) reg = old | src; break;
          default: if (rs1 != 0) reg = old & ~src;
        }
        set(rd, old);
        break;
      }
      default: return fail("opcode " + std::to_string(opcode));
    }
    pc = pc_next;
    return true;
  }

  /// riscv-vp's --intercept-syscalls: write (64) and exit (93); anything else traps.
  bool ecall(std::uint32_t next) {
    if (x[17] == 64u) {
      const std::uint32_t buf = x[11], len = x[12];
      if (std::uint64_t(buf) + len > ram_size) return fail("write outside RAM");
      console.append(reinterpret_cast<const char*>(&ram[buf]), len);
      x[10] = len;
      pc = next;
      return true;
    }
    if (x[17] == 93u) {
      exit_code = static_cast<std::int32_t>(x[10]);
      exited = true;
      return false;
    }
    trap(11, 0, pc);
    return true;
  }

 private:
  void run() {
    while (step()) {
    }
    sc_core::sc_stop();
  }
};

}  // namespace firmware_targets
}  // namespace specular

#endif  // SPECULAR_TESTS_SUPPORT_RV32_HART_H
