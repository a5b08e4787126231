/// \file
/// The bit fields of the register map (register_map.h), written once as a table: each
/// field's position, width, access, description and, for an enumerated field, which
/// enumeration its values come from.
///
/// register_map.h gives each row's offset, access and reset as one 32-bit word and the
/// bits of STATUS, CONTROL and CONFIG as constants (status_bits, control_bits,
/// config_bits); this table names every field of every row, and the static_asserts below
/// tie it to those constants and to config_word(), so it cannot drift from them. Every
/// description of the map for other tools comes from here: the firmware C header
/// (firmware/include/specular/specular_regs.h, specular_firmware_header, docs/firmware.md)
/// and the IP-XACT component and SystemRDL addrmap (ip/, specular_ip_export,
/// docs/ipxact.md). Kernel-free: no SystemC.
///
/// Names: upper case C identifiers, the names firmware uses (SPECULAR_<REG>_<FIELD>_*):
/// CONFIG's fraction widths are COS_FRAC_BITS and OUT_FRAC_BITS, like RGB_BITS beside
/// them, since they hold a number of bits, not a fraction. Enumerated values are named
/// the same way, after the C++ enumerator's to_string ("device-energy" → DEVICE_ENERGY).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "specular/tlm/register_map.h"

namespace specular {

/// Which enumeration a field's values come from (none: a plain number).
enum class FieldValues : std::uint8_t {
  none,           ///< a plain number
  error_cause,    ///< ErrorCause: STATUS[15:8]
  normalisation,  ///< Normalisation: CONFIG[1:0]
  saturation,     ///< Saturation: CONFIG[4]
  constants,      ///< Constants: CONFIG[6:5]
};

/// One bit field of a register.
struct FieldInfo {
  Reg reg;           ///< the register holding the field
  const char* name;  ///< upper case, a C identifier
  unsigned shift;    ///< lowest bit
  unsigned width;    ///< bits
  /// read_only, read_write; write_1_to_clear: writing 1 clears it; self_clearing: a
  /// write of 1 acts, the field reads 0.
  Access access;
  FieldValues values;       ///< the enumeration of its values, or none
  const char* description;  ///< one line for the docs and the firmware header

  /// The field's bits in place: ((1 << width) − 1) << shift.
  constexpr std::uint32_t mask() const {
    return (width >= 32 ? 0xFFFFFFFFu : ((1u << width) - 1u)) << shift;
  }
};

/// The fields of the rows that have more than one (or one narrower than the word),
/// grouped by register in the map's order, lowest bit first. Other rows are one 32-bit
/// field VALUE (fields_of).
inline constexpr FieldInfo register_fields[] = {
    // clang-format off
    {Reg::version, "MINOR",         0,                                16, Access::read_only,        FieldValues::none,          "Minor version: compatible additions"},
    {Reg::version, "MAJOR",         16,                               16, Access::read_only,        FieldValues::none,          "Major version: bumped on incompatible changes; a driver refuses another"},
    {Reg::config,  "NORMALISATION", config_bits::normalisation_shift, 2,  Access::read_only,        FieldValues::normalisation, "What ROM 38 holds: the normalisation policy"},
    {Reg::config,  "SATURATION",    config_bits::saturation_shift,    1,  Access::read_only,        FieldValues::saturation,    "What adder 8 does with a negative result"},
    {Reg::config,  "CONSTANTS",     config_bits::constants_shift,     2,  Access::read_only,        FieldValues::constants,     "The constants on pins 19 (h) and 20 (a) and ROM 38's scale"},
    {Reg::config,  "COS_FRAC_BITS", config_bits::cos_frac_shift,      8,  Access::read_only,        FieldValues::none,          "Fraction bits of COS (U1.F): 1.0 is 1 << F"},
    {Reg::config,  "OUT_FRAC_BITS", config_bits::out_frac_shift,      8,  Access::read_only,        FieldValues::none,          "Fraction bits of OUT_R, OUT_G, OUT_B (signed)"},
    {Reg::config,  "RGB_BITS",      config_bits::rgb_bits_shift,      8,  Access::read_only,        FieldValues::none,          "Width of R, G, B: the largest is (1 << W) - 1"},
    {Reg::status,  "BUSY",          0,                                1,  Access::read_only,        FieldValues::none,          "An operation is in flight (the pin model only; lt, rtl and rtl-sync finish inside the access)"},
    {Reg::status,  "DONE",          1,                                1,  Access::write_1_to_clear, FieldValues::none,          "Results valid; drives done_irq; write 1 to clear"},
    {Reg::status,  "ERROR",         2,                                1,  Access::write_1_to_clear, FieldValues::none,          "An access was refused; write 1 to clear (clears CAUSE and ERROR_ADDRESS too)"},
    {Reg::status,  "CAUSE",         status_bits::cause_shift,         8,  Access::read_only,        FieldValues::error_cause,   "Why the last access was refused (ErrorCause)"},
    {Reg::control, "START",         0,                                1,  Access::self_clearing,    FieldValues::none,          "Write 1: run one operation on COS, N, R, G, B; reads 0; any other bit is refused"},
    // clang-format on
};
/// Rows of register_fields.
constexpr std::size_t field_count = sizeof register_fields / sizeof register_fields[0];

/// The fields of `reg`, lowest bit first: its rows of register_fields, or one 32-bit
/// field VALUE with the row's access and description.
std::vector<FieldInfo> fields_of(Reg reg);

/// How many values an enumeration has (codes 0 to count-1; 0 for none).
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

/// One value of an enumerated field.
struct FieldValue {
  std::string name;  ///< upper case, a C identifier (e.g. "DEVICE_ENERGY")
  std::uint32_t value;      ///< the field's code for it
  std::string description;  ///< error causes say why; a policy's is empty (its name says it)
};

/// The values of an enumerated field, codes 0 to value_count(values) - 1 in order;
/// empty for FieldValues::none.
std::vector<FieldValue> field_values(FieldValues values);

namespace detail {
constexpr std::uint32_t fields_mask(Reg reg) {
  std::uint32_t m = 0;
  for (const FieldInfo& f : register_fields)
    if (f.reg == reg) m |= f.mask();
  return m;
}
constexpr bool register_fields_are_consistent() {
  for (std::size_t i = 0; i < field_count; ++i) {
    const FieldInfo& f = register_fields[i];
    if (f.width == 0 || f.shift + f.width > 32) return false;
    if (info(f.reg).words != 1) return false;  // windows take their registers' fields
    for (std::size_t j = 0; j < i; ++j) {
      const FieldInfo& g = register_fields[j];
      if (g.reg == f.reg && ((g.mask() & f.mask()) != 0 || g.shift > f.shift)) return false;
      if (g.reg != f.reg && info(g.reg).offset > info(f.reg).offset) return false;  // map order
    }
    // an enumeration fits its field
    if (value_count(f.values) > 0 && value_count(f.values) - 1 > (f.mask() >> f.shift))
      return false;
  }
  return true;
}
constexpr std::uint32_t field_mask(Reg reg, std::size_t nth) {
  for (const FieldInfo& f : register_fields)
    if (f.reg == reg && nth-- == 0) return f.mask();
  return 0;
}
}  // namespace detail

static_assert(detail::register_fields_are_consistent(),
              "register_fields: fields inside 32 bits, on single registers, in the map's order, "
              "lowest bit first, not overlapping, enumerations fitting their fields");
// The table says what register_map.h's constants say.
static_assert(detail::field_mask(Reg::status, 0) == status_bits::busy &&
                  detail::field_mask(Reg::status, 1) == status_bits::done &&
                  detail::field_mask(Reg::status, 2) == status_bits::error &&
                  detail::field_mask(Reg::status, 3) == status_bits::cause_mask &&
                  detail::field_mask(Reg::status, 4) == 0,
              "register_fields: STATUS differs from status_bits");
static_assert(detail::fields_mask(Reg::control) == control_bits::defined &&
                  detail::field_mask(Reg::control, 0) == control_bits::start,
              "register_fields: CONTROL differs from control_bits (the bits a write may set)");
static_assert(detail::field_mask(Reg::config, 0) == 3u << config_bits::normalisation_shift &&
                  detail::field_mask(Reg::config, 1) == 1u << config_bits::saturation_shift &&
                  detail::field_mask(Reg::config, 2) == 3u << config_bits::constants_shift &&
                  detail::field_mask(Reg::config, 3) == 0xFFu << config_bits::cos_frac_shift &&
                  detail::field_mask(Reg::config, 4) == 0xFFu << config_bits::out_frac_shift &&
                  detail::field_mask(Reg::config, 5) == 0xFFu << config_bits::rgb_bits_shift &&
                  detail::field_mask(Reg::config, 6) == 0,
              "register_fields: CONFIG differs from config_bits' shifts");
// Every CONFIG word config_word() can make, and the reset, lie inside the fields.
static_assert((config_word(Normalisation::device_energy, Saturation::literal, 255, 255, 255,
                           Constants::minimax) &
               ~detail::fields_mask(Reg::config)) == 0,
              "register_fields: config_word sets bits outside the CONFIG fields");
static_assert((info(Reg::config).reset & ~detail::fields_mask(Reg::config)) == 0,
              "register_fields: CONFIG's reset sets a bit no field holds");
static_assert(detail::field_mask(Reg::version, 0) == 0x0000FFFFu &&
                  detail::field_mask(Reg::version, 1) == 0xFFFF0000u,
              "register_fields: VERSION is (major << 16) | minor");

}  // namespace specular
