/// \file
/// The register map of the TLM-2.0 target, written once as a table (VCML style:
/// name, offset, access, reset value, description on one line).
///
/// Everything else reads this table: the target decodes addresses with it, the
/// driver takes offsets from it, docs/tlm/registers.md prints it (a test keeps them equal).
/// Registers are 32 bits wide; data travels in the host's byte order, as the TLM-2.0
/// generic payload's data array does.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "specular/core.h"

namespace specular {

/// What a bus access may do to a register.
enum class Access : std::uint8_t {
  read_only,         ///< writes get TLM_COMMAND_ERROR_RESPONSE
  read_write,        ///< plain storage (values are range-checked on write)
  write_1_to_clear,  ///< reads state; writing 1 to a flag clears it (STATUS)
  self_clearing,     ///< a write acts (START); reads return 0
};

/// "RO", "RW", "R/W1C" or "W (reads 0)": the access as the docs' tables write it.
const char* to_string(Access access);

/// Index of every row of the table; the row's position equals its index.
enum class Reg : std::uint8_t {
  id,  ///< ID: identification, 0x00059965
  version,  ///< VERSION: register map version
  config,  ///< CONFIG: the configuration, fixed at construction
  status,  ///< STATUS: busy, done, error, cause (W1C)
  control,  ///< CONTROL: START
  batch_capacity,  ///< BATCH_CAPACITY: operations per batch
  error_address,  ///< ERROR_ADDRESS: offset of the last refused access
  cos,  ///< COS: cos λ code → register 1 (pin 17)
  n,  ///< N: exponent n → register 2 (pin 18)
  r,  ///< R: intensity → register 10 (pin 21)
  g,  ///< G: intensity → register 11 (pin 22)
  b,  ///< B: intensity → register 12 (pin 23)
  out_r,  ///< OUT_R: pin 24
  out_g,  ///< OUT_G: pin 25
  out_b,  ///< OUT_B: pin 26
  reg1,  ///< REG1: register 1 of the last operation
  reg9_pass1_lo,  ///< REG9_PASS1_LO: register 9 after pass 1, bits 31:0
  reg9_pass1_hi,  ///< REG9_PASS1_HI: ... bits 63:32
  reg9_pass2_lo,  ///< REG9_PASS2_LO: register 9 after pass 2, bits 31:0
  reg9_pass2_hi,  ///< REG9_PASS2_HI: ... bits 63:32
  rom38_k,  ///< ROM38_K: ROM 38 word of the last operation
  norm39,  ///< NORM39: multiplier 39 output of the last operation
  pin19_h,  ///< PIN19_H: the constant h on pin 19
  pin20_a,  ///< PIN20_A: the constant a on pin 20
  operands,   ///< window: COS, N, R, G, B, CONTROL as one burst (aliases)
  results,    ///< window: OUT_R, OUT_G, OUT_B as one burst (aliases)
  batch_cos,  ///< window: one cos code per operation
  batch_out,  ///< window: three output codes (R, G, B) per operation
  count  ///< the number of rows (not a row)
};

/// Rows of register_map (registers and windows): 28.
constexpr std::size_t register_count = static_cast<std::size_t>(Reg::count);
/// The row index of `reg` in register_map.
constexpr std::size_t index_of(Reg reg) { return static_cast<std::size_t>(reg); }

/// Why the last access was refused (STATUS bits 15:8).
enum class ErrorCause : std::uint8_t {
  none = 0,              ///< no error since the last clear
  cos_out_of_range = 1,  ///< COS / BATCH_COS word above 1.0 (65536 for U1.16)
  n_out_of_range = 2,    ///< N outside 1..1000
  rgb_out_of_range = 3,  ///< R, G or B above 255 (the RGB format's maximum)
  read_only = 4,         ///< write to a read-only register
  reserved_bits = 5,     ///< CONTROL written with an undefined bit set
  busy = 6,              ///< START or operand write while an operation is in flight
  address = 7,           ///< unmapped or misaligned address, or a burst past a window
  burst = 8,             ///< a length the row does not take, sub-word window write, streaming
  byte_enable = 9,       ///< byte enables other than "all bytes"
  command = 10,          ///< a command other than read, write, ignore
};

/// The cause's name as the enumerator spells it ("cos_out_of_range").
const char* to_string(ErrorCause cause);
/// What the cause means, for docs and error messages.
const char* describe(ErrorCause cause);
/// ErrorCause's values: codes 0 to 10.
constexpr std::uint8_t error_cause_count = 11;

/// One row of the register map.
struct RegisterInfo {
  Reg reg;               ///< the row's index
  const char* name;      ///< upper case, as the docs and the firmware header spell it
  std::uint32_t offset;  ///< byte offset from the target's base address
  std::uint32_t words;   ///< 1 for a register, more for a window (burst-accessible)
  Access access;         ///< what a bus access may do
  std::uint32_t reset;   ///< value after construction (a window of aliases: reset_of_word)
  /// Why a written value is refused (none: any value is taken). Read-only rows need
  /// none: every write to them is refused with read_only.
  ErrorCause value_check;
  const char* description;  ///< one line for the docs' table and the firmware header

  /// The byte offset just past the row: offset + 4·words.
  constexpr std::uint32_t end() const { return offset + 4 * words; }
};

/// Operations per batch transaction: the BATCH_COS window holds this many cos codes,
/// BATCH_OUT three times as many output codes.
constexpr std::uint32_t batch_capacity = 1024;

/// Identification: the patent number, readable in a hex dump (UA 59965 U).
constexpr std::uint32_t device_id = 0x00059965;
/// Register map version, major << 16 | minor. Bump major on incompatible changes.
constexpr std::uint32_t map_version = 0x00010001;  // 1.1: CONFIG[6:5], PIN19_H, PIN20_A

// ---- STATUS fields ----------------------------------------------------------------
/// STATUS's bits (register_fields has the same as a table).
namespace status_bits {
constexpr std::uint32_t busy = 1u << 0;   ///< an operation is in flight (pin model only)
constexpr std::uint32_t done = 1u << 1;   ///< results valid; W1C; drives the done IRQ
constexpr std::uint32_t error = 1u << 2;  ///< an access was refused; W1C (clears cause too)
constexpr int cause_shift = 8;            ///< bits 15:8: ErrorCause of the last refusal
constexpr std::uint32_t cause_mask = 0xFFu << cause_shift;  ///< bits 15:8 in place
}  // namespace status_bits

// ---- CONTROL fields ---------------------------------------------------------------
/// CONTROL's bits.
namespace control_bits {
constexpr std::uint32_t start = 1u << 0;  ///< run one operation on COS, N, R, G, B
constexpr std::uint32_t defined = start;  ///< writing any other bit is refused
}  // namespace control_bits

// ---- CONFIG fields (read-only, fixed at construction like ROM 38's contents) ------
/// CONFIG's fields: where each starts (config_word() packs them).
namespace config_bits {
constexpr int normalisation_shift = 0;  ///< bits 1:0: 0 patent, 1 energy, 2 none, 3 device-energy
constexpr int saturation_shift = 4;     ///< bit 4: 0 clamp, 1 literal
constexpr int constants_shift = 5;      ///< bits 6:5: 0 patent, 1 minimax-half, 2 minimax
constexpr int cos_frac_shift = 8;       ///< bits 15:8: fraction bits of COS (U1.F)
constexpr int out_frac_shift = 16;      ///< bits 23:16: fraction bits of OUT_* (signed)
constexpr int rgb_bits_shift = 24;      ///< bits 31:24: width of R, G, B
}  // namespace config_bits

/// The CONFIG word for a configuration.
constexpr std::uint32_t config_word(Normalisation normalisation, Saturation saturation,
                                    int cos_frac_bits, int out_frac_bits, int rgb_bits,
                                    Constants constants = Constants::patent) {
  return (static_cast<std::uint32_t>(normalisation) << config_bits::normalisation_shift) |
         (static_cast<std::uint32_t>(constants) << config_bits::constants_shift) |
         (static_cast<std::uint32_t>(saturation) << config_bits::saturation_shift) |
         (static_cast<std::uint32_t>(cos_frac_bits) << config_bits::cos_frac_shift) |
         (static_cast<std::uint32_t>(out_frac_bits) << config_bits::out_frac_shift) |
         (static_cast<std::uint32_t>(rgb_bits) << config_bits::rgb_bits_shift);
}
/// The CONFIG word a target built with `config` reads.
std::uint32_t config_word(const Config& config);


/// THE register map. Offsets are bytes from the base address.
inline constexpr std::array<RegisterInfo, register_count> register_map{{
    // clang-format off
    {Reg::id,             "ID",             0x000, 1, Access::read_only,        device_id,   ErrorCause::none,              "Identification: 0x00059965 (patent UA 59965 U)"},
    {Reg::version,        "VERSION",        0x004, 1, Access::read_only,        map_version, ErrorCause::none,              "Register map version: (major << 16) + minor"},
    {Reg::config,         "CONFIG",         0x008, 1, Access::read_only,        config_word(Normalisation::patent, Saturation::clamp, 16, 13, 8), ErrorCause::none,
                                                                                             "[1:0] normalisation (0 patent, 1 energy, 2 none, 3 device-energy), [4] saturation (0 clamp, 1 literal), [6:5] constants (0 patent, 1 minimax-half, 2 minimax), [15:8] COS fraction bits, [23:16] OUT fraction bits, [31:24] RGB bits; fixed at construction (reset shown for the defaults)"},
    {Reg::status,         "STATUS",         0x00C, 1, Access::write_1_to_clear, 0,           ErrorCause::none,              "[0] busy, [1] done (W1C, drives done_irq), [2] error (W1C, clears cause and ERROR_ADDRESS), [15:8] error cause"},
    {Reg::control,        "CONTROL",        0x010, 1, Access::self_clearing,    0,           ErrorCause::reserved_bits,     "[0] START: run one operation on COS, N, R, G, B; other bits refused; reads 0"},
    {Reg::batch_capacity, "BATCH_CAPACITY", 0x014, 1, Access::read_only,        batch_capacity, ErrorCause::none,             "Operations per batch transaction (BATCH_COS words)"},
    {Reg::error_address,  "ERROR_ADDRESS",  0x018, 1, Access::read_only,        0,           ErrorCause::none,              "Byte offset of the last refused access (the offending word in a burst); 0xFFFFFFFF for an address above 32 bits"},
    {Reg::cos,            "COS",            0x020, 1, Access::read_write,       0,           ErrorCause::cos_out_of_range,  "cos λ code, U1.16: 0..65536 (= 1.0); larger is refused"},
    {Reg::n,              "N",              0x024, 1, Access::read_write,       1,           ErrorCause::n_out_of_range,    "Specular exponent n: 1..1000; other values are refused"},
    {Reg::r,              "R",              0x028, 1, Access::read_write,       0,           ErrorCause::rgb_out_of_range,  "Light intensity R (register 10): 0..255"},
    {Reg::g,              "G",              0x02C, 1, Access::read_write,       0,           ErrorCause::rgb_out_of_range,  "Light intensity G (register 11): 0..255"},
    {Reg::b,              "B",              0x030, 1, Access::read_write,       0,           ErrorCause::rgb_out_of_range,  "Light intensity B (register 12): 0..255"},
    {Reg::out_r,          "OUT_R",          0x040, 1, Access::read_only,        0,           ErrorCause::none,              "Pin 24: K·A·R, S18.13 two's complement"},
    {Reg::out_g,          "OUT_G",          0x044, 1, Access::read_only,        0,           ErrorCause::none,              "Pin 25: K·A·G, S18.13 two's complement"},
    {Reg::out_b,          "OUT_B",          0x048, 1, Access::read_only,        0,           ErrorCause::none,              "Pin 26: K·A·B, S18.13 two's complement"},
    {Reg::reg1,           "REG1",           0x050, 1, Access::read_only,        0,           ErrorCause::none,              "Inspection: register 1 (cos code used) of the last operation"},
    {Reg::reg9_pass1_lo,  "REG9_PASS1_LO",  0x054, 1, Access::read_only,        0,           ErrorCause::none,              "Inspection: register 9 after pass 1, S14.22, bits 31:0"},
    {Reg::reg9_pass1_hi,  "REG9_PASS1_HI",  0x058, 1, Access::read_only,        0,           ErrorCause::none,              "... bits 63:32 (sign-extended)"},
    {Reg::reg9_pass2_lo,  "REG9_PASS2_LO",  0x05C, 1, Access::read_only,        0,           ErrorCause::none,              "Inspection: register 9 after pass 2 (A), S14.22, bits 31:0"},
    {Reg::reg9_pass2_hi,  "REG9_PASS2_HI",  0x060, 1, Access::read_only,        0,           ErrorCause::none,              "... bits 63:32 (sign-extended)"},
    {Reg::rom38_k,        "ROM38_K",        0x064, 1, Access::read_only,        0,           ErrorCause::none,              "Inspection: ROM 38 word s·K(n), U9.16"},
    {Reg::norm39,         "NORM39",         0x068, 1, Access::read_only,        0,           ErrorCause::none,              "Inspection: multiplier 39 output s·K·A, S10.20"},
    {Reg::pin19_h,        "PIN19_H",        0x06C, 1, Access::read_only,        0x80,        ErrorCause::none,              "Pin 19: the constant h, U10.8 code (0x80 = ½, the patent's); fixed at construction by CONFIG's constants"},
    {Reg::pin20_a,        "PIN20_A",        0x070, 1, Access::read_only,        0x400000,    ErrorCause::none,              "Pin 20: the constant a, S14.22 code (0x400000 = 1.0, the patent's); fixed at construction by CONFIG's constants"},
    {Reg::operands,       "OPERANDS",       0x080, 6, Access::read_write,       0,           ErrorCause::none,              "Operand block: words 0–5 are COS, N, R, G, B, CONTROL (the registers above); a burst writes any contiguous part, all words checked before any is stored; START in word 5 then runs the operation"},
    {Reg::results,        "RESULTS",        0x0A0, 3, Access::read_only,        0,           ErrorCause::none,              "Result block: OUT_R, OUT_G, OUT_B (the registers above) in one burst read"},
    {Reg::batch_cos,      "BATCH_COS",      0x1000, batch_capacity, Access::read_write, 0, ErrorCause::cos_out_of_range, "Batch window: a burst write of k cos codes at word i runs k operations (N, R, G, B shared), results to BATCH_OUT word 3i"},
    {Reg::batch_out,      "BATCH_OUT",      0x4000, 3 * batch_capacity, Access::read_only, 0, ErrorCause::none, "Batch results: OUT_R, OUT_G, OUT_B of operation i at words 3i, 3i+1, 3i+2"},
    // clang-format on
}};

/// Bytes the target decodes from its base address (a router's window size).
constexpr std::uint32_t map_size = 0x8000;

/// The row of `reg`.
constexpr const RegisterInfo& info(Reg reg) { return register_map[index_of(reg)]; }
/// The byte offset of `reg` from the base address.
constexpr std::uint32_t offset_of(Reg reg) { return info(reg).offset; }

namespace detail {
constexpr bool map_is_consistent() {
  for (std::size_t i = 0; i < register_count; ++i) {
    const RegisterInfo& row = register_map[i];
    if (index_of(row.reg) != i) return false;                         // row order = enum order
    if (row.offset % 4 != 0 || row.words == 0) return false;          // word-aligned
    if (i > 0 && row.offset < register_map[i - 1].end()) return false;  // sorted, no overlap
    if (row.end() > map_size) return false;
  }
  return true;
}
}  // namespace detail
static_assert(detail::map_is_consistent(),
              "register_map rows must follow Reg's order, be word-aligned and not overlap");

/// The single register behind word `index` (0..5) of the OPERANDS block.
constexpr Reg operand_register(std::uint32_t index) {
  constexpr Reg block[] = {Reg::cos, Reg::n, Reg::r, Reg::g, Reg::b, Reg::control};
  return block[index];
}
/// Words of the OPERANDS block: COS, N, R, G, B, CONTROL.
constexpr std::uint32_t operand_words = 6;
/// The single register behind word `index` (0..2) of the RESULTS block.
constexpr Reg result_register(std::uint32_t index) {
  constexpr Reg block[] = {Reg::out_r, Reg::out_g, Reg::out_b};
  return block[index];
}

/// What word `index` of `row` reads after construction (the defaults shown for CONFIG,
/// PIN19_H, PIN20_A): OPERANDS and RESULTS read the registers they alias.
constexpr std::uint32_t reset_of_word(const RegisterInfo& row, std::uint32_t index) {
  if (row.reg == Reg::operands) return info(operand_register(index)).reset;
  if (row.reg == Reg::results) return info(result_register(index)).reset;
  return row.reset;
}
static_assert(info(Reg::operands).words == operand_words &&
                  info(Reg::results).words == 3,
              "OPERANDS holds COS, N, R, G, B, CONTROL; RESULTS holds OUT_R, OUT_G, OUT_B");

/// The row whose range holds `offset`, or nullptr (unmapped or not word-aligned).
const RegisterInfo* decode(std::uint64_t offset);

// The docs' tables, printed from the table above (docs/tlm/registers.md and
// docs/misuse.md carry exactly these between marker comments; specular_register_docs
// rewrites them).
/// The register map: offset, name, access, reset, description.
std::string register_map_markdown();
/// The error causes (STATUS[15:8]).
std::string error_cause_markdown();
/// The whole decoded space, holes included: access, reset value and what refuses a
/// write (or any access, for a hole).
std::string address_map_markdown();

}  // namespace specular
