// Who writes each row of the register map, beyond what its Access says: what a
// hardware description of the register file needs (the Verilog register block, and
// IP-XACT's `volatile`). A switch over Reg with no default, so a new row does not
// compile (-Wswitch, -Werror) until someone says who writes it.
#pragma once

#include "specular/tlm/register_map.h"

namespace specular {
namespace ip_export {

enum class RowRole {
  constant,        ///< fixed by the map (ID, VERSION)
  configured,      ///< fixed when the device is built (CONFIG, PIN19_H, PIN20_A, BATCH_CAPACITY)
  storage,         ///< software writes it, range-checked (COS, N, R, G, B)
  status,          ///< STATUS: hardware sets, software clears (W1C)
  command,         ///< CONTROL: a write acts, reads 0
  refusal_record,  ///< ERROR_ADDRESS: the register block writes it on a refusal
  hardware,        ///< the device writes it at the end of an operation (results, inspection)
  alias_window,    ///< OPERANDS, RESULTS: words that are the registers above
  memory_window,   ///< BATCH_COS, BATCH_OUT: memories
};

constexpr RowRole role_of(Reg reg) {
  switch (reg) {
    case Reg::id:
    case Reg::version: return RowRole::constant;
    case Reg::config:
    case Reg::batch_capacity:
    case Reg::pin19_h:
    case Reg::pin20_a: return RowRole::configured;
    case Reg::status: return RowRole::status;
    case Reg::control: return RowRole::command;
    case Reg::error_address: return RowRole::refusal_record;
    case Reg::cos:
    case Reg::n:
    case Reg::r:
    case Reg::g:
    case Reg::b: return RowRole::storage;
    case Reg::out_r:
    case Reg::out_g:
    case Reg::out_b:
    case Reg::reg1:
    case Reg::reg9_pass1_lo:
    case Reg::reg9_pass1_hi:
    case Reg::reg9_pass2_lo:
    case Reg::reg9_pass2_hi:
    case Reg::rom38_k:
    case Reg::norm39: return RowRole::hardware;
    case Reg::operands:
    case Reg::results: return RowRole::alias_window;
    case Reg::batch_cos:
    case Reg::batch_out: return RowRole::memory_window;
    case Reg::count: break;
  }
  return RowRole::constant;
}

/// Whether something other than a bus write changes what the row reads (IP-XACT's
/// `volatile`): STATUS, ERROR_ADDRESS, the device's results, and windows over them.
constexpr bool is_volatile(Reg reg) {
  const RowRole role = role_of(reg);
  return role == RowRole::status || role == RowRole::refusal_record ||
         role == RowRole::hardware || reg == Reg::results || reg == Reg::batch_out;
}

}  // namespace ip_export
}  // namespace specular
