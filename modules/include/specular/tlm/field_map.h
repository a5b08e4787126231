// The fields of the register map (register_map.h): each register's bit fields, their
// access and their enumerated values, written once as a table.
//
// register_map.h gives each row's offset, access and reset as one 32-bit word and the
// bits of STATUS, CONTROL and CONFIG as constants; this table names every field of
// every row, so that a description of the map for other tools (IP-XACT, SystemRDL:
// specular_ip_export, docs/ipxact.md) comes from the one source. The static_asserts
// below tie it to those constants. Rows without a listed field are one 32-bit field,
// `value`, with the row's access. Kernel-free: no SystemC.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "specular/format.h"
#include "specular/tlm/register_map.h"

namespace specular {

/// Which enumeration a field's values name (none: a plain number).
enum class FieldValues : std::uint8_t { none, error_cause, normalisation, saturation, constants };

/// One bit field of a register.
struct FieldInfo {
  Reg reg;
  const char* name;
  unsigned shift;  ///< lowest bit
  unsigned width;  ///< bits
  /// read_only, read_write; write_1_to_clear: writing 1 clears it; self_clearing: a
  /// write of 1 acts, the field reads 0.
  Access access;
  FieldValues values;
  const char* description;

  constexpr std::uint32_t mask() const {
    return (width >= 32 ? 0xFFFFFFFFu : ((1u << width) - 1u)) << shift;
  }
};

/// The fields of the rows that have more than one (or one narrower than the word).
inline constexpr std::array<FieldInfo, 13> field_map{{
    // clang-format off
    {Reg::version, "MINOR",         0,  16, Access::read_only,        FieldValues::none,          "Minor version: compatible additions"},
    {Reg::version, "MAJOR",         16, 16, Access::read_only,        FieldValues::none,          "Major version: bumped on incompatible changes"},
    {Reg::config,  "NORMALISATION", 0,  2,  Access::read_only,        FieldValues::normalisation, "What ROM 38 holds: the normalisation policy"},
    {Reg::config,  "SATURATION",    4,  1,  Access::read_only,        FieldValues::saturation,    "What adder 8 does with a negative result"},
    {Reg::config,  "CONSTANTS",     5,  2,  Access::read_only,        FieldValues::constants,     "The constants on pins 19 (h) and 20 (a) and ROM 38's scale"},
    {Reg::config,  "COS_FRAC",      8,  8,  Access::read_only,        FieldValues::none,          "Fraction bits of COS (U1.F)"},
    {Reg::config,  "OUT_FRAC",      16, 8,  Access::read_only,        FieldValues::none,          "Fraction bits of OUT_R, OUT_G, OUT_B (signed)"},
    {Reg::config,  "RGB_BITS",      24, 8,  Access::read_only,        FieldValues::none,          "Width of R, G, B"},
    {Reg::status,  "BUSY",          0,  1,  Access::read_only,        FieldValues::none,          "An operation is in flight (pin model only)"},
    {Reg::status,  "DONE",          1,  1,  Access::write_1_to_clear, FieldValues::none,          "Results valid; drives done_irq; write 1 to clear"},
    {Reg::status,  "ERROR",         2,  1,  Access::write_1_to_clear, FieldValues::none,          "An access was refused; write 1 to clear (clears CAUSE and ERROR_ADDRESS too)"},
    {Reg::status,  "CAUSE",         8,  8,  Access::read_only,        FieldValues::error_cause,   "Why the last access was refused"},
    {Reg::control, "START",         0,  1,  Access::self_clearing,    FieldValues::none,          "Write 1: run one operation on COS, N, R, G, B; reads 0; other bits are refused"},
    // clang-format on
}};

/// The fields of `reg`, lowest bit first: its rows of field_map, or one 32-bit field
/// `VALUE` with the row's access and description.
inline std::vector<FieldInfo> fields_of(Reg reg) {
  std::vector<FieldInfo> fields;
  for (const FieldInfo& f : field_map)
    if (f.reg == reg) fields.push_back(f);
  if (fields.empty()) {
    const RegisterInfo& row = info(reg);
    fields.push_back({reg, "VALUE", 0, 32, row.access, FieldValues::none, row.description});
  }
  return fields;
}

/// How many values an enumeration has (codes 0 .. count-1).
constexpr std::uint32_t value_count(FieldValues values) {
  switch (values) {
    case FieldValues::none: return 0;
    case FieldValues::error_cause: return error_cause_count;
    case FieldValues::normalisation: return static_cast<std::uint32_t>(Normalisation::device_energy) + 1;
    case FieldValues::saturation: return static_cast<std::uint32_t>(Saturation::literal) + 1;
    case FieldValues::constants: return static_cast<std::uint32_t>(Constants::minimax) + 1;
  }
  return 0;
}

/// The name of code `code` of an enumeration: the C++ enumerator's to_string.
inline std::string value_name(FieldValues values, std::uint32_t code) {
  switch (values) {
    case FieldValues::none: break;
    case FieldValues::error_cause: return to_string(static_cast<ErrorCause>(code));
    case FieldValues::normalisation: return to_string(static_cast<Normalisation>(code));
    case FieldValues::saturation: return to_string(static_cast<Saturation>(code));
    case FieldValues::constants: return to_string(static_cast<Constants>(code));
  }
  return std::to_string(code);
}

/// What code `code` means (error causes say why; the policies have their names only).
inline std::string value_description(FieldValues values, std::uint32_t code) {
  if (values == FieldValues::error_cause) return describe(static_cast<ErrorCause>(code));
  return value_name(values, code);
}

namespace detail {
constexpr std::uint32_t fields_mask(Reg reg) {
  std::uint32_t m = 0;
  for (const FieldInfo& f : field_map)
    if (f.reg == reg) m |= f.mask();
  return m;
}
constexpr bool field_map_is_consistent() {
  for (std::size_t i = 0; i < field_map.size(); ++i) {
    const FieldInfo& f = field_map[i];
    if (f.width == 0 || f.shift + f.width > 32) return false;
    if (info(f.reg).words != 1) return false;  // windows take their registers' fields
    for (std::size_t j = 0; j < i; ++j)  // fields of a row do not overlap, lowest bit first
      if (field_map[j].reg == f.reg && ((field_map[j].mask() & f.mask()) != 0 || field_map[j].shift > f.shift))
        return false;
    // an enumeration fits its field
    if (value_count(f.values) > 0 && value_count(f.values) - 1 > (f.mask() >> f.shift))
      return false;
  }
  return true;
}
constexpr std::uint32_t field_mask(Reg reg, std::size_t nth) {
  for (const FieldInfo& f : field_map)
    if (f.reg == reg && nth-- == 0) return f.mask();
  return 0;
}
}  // namespace detail

static_assert(detail::field_map_is_consistent(),
              "field_map: fields inside 32 bits, on single registers, lowest bit first, not "
              "overlapping, enumerations fitting their fields");
// The table says what register_map.h's constants say.
static_assert(detail::field_mask(Reg::status, 0) == status_bits::busy &&
                  detail::field_mask(Reg::status, 1) == status_bits::done &&
                  detail::field_mask(Reg::status, 2) == status_bits::error &&
                  detail::field_mask(Reg::status, 3) == status_bits::cause_mask,
              "field_map's STATUS fields are status_bits'");
static_assert(detail::fields_mask(Reg::control) == control_bits::defined,
              "field_map's CONTROL fields are the bits a write may set");
static_assert(detail::field_mask(Reg::config, 0) == 3u << config_bits::normalisation_shift &&
                  detail::field_mask(Reg::config, 1) == 1u << config_bits::saturation_shift &&
                  detail::field_mask(Reg::config, 2) == 3u << config_bits::constants_shift &&
                  detail::field_mask(Reg::config, 3) == 0xFFu << config_bits::cos_frac_shift &&
                  detail::field_mask(Reg::config, 4) == 0xFFu << config_bits::out_frac_shift &&
                  detail::field_mask(Reg::config, 5) == 0xFFu << config_bits::rgb_bits_shift,
              "field_map's CONFIG fields are config_bits' shifts");
// Every CONFIG word config_word() can make lies inside the fields.
static_assert((config_word(Normalisation::device_energy, Saturation::literal, 255, 255, 255,
                           Constants::minimax) &
               ~detail::fields_mask(Reg::config)) == 0,
              "config_word sets bits outside field_map's CONFIG fields");
static_assert(detail::fields_mask(Reg::version) == 0xFFFFFFFFu,
              "VERSION is major << 16 | minor");

}  // namespace specular
