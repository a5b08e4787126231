// The fields inside the register map's registers (STATUS, CONTROL, CONFIG) as a table:
// bit position, width, access and, for an enumerated field, which enumeration its
// values come from. register_map.h gives each field's position (status_bits,
// control_bits, config_bits); this table adds the widths that were only comments there,
// and static_asserts below tie the two together, so the table cannot drift from them.
//
// Generators read it: the firmware C header (firmware/include/specular/specular_regs.h,
// written by specular_firmware_header) takes every field and every enumerated value
// from here, so firmware and the C++ map cannot differ.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "specular/rom38_banks.h"
#include "specular/tlm/register_map.h"

namespace specular {

/// Where an enumerated field's values come from (none: a plain number).
enum class FieldValues : std::uint8_t {
  none,
  error_cause,    ///< ErrorCause: STATUS[15:8]
  normalisation,  ///< Normalisation: CONFIG[1:0]
  saturation,     ///< Saturation: CONFIG[4]
  constants,      ///< Constants: CONFIG[6:5]
};

/// One field of a register.
struct FieldInfo {
  Reg reg;
  const char* name;  ///< upper case, a C identifier
  int shift;         ///< lowest bit
  int width;         ///< bits
  Access access;
  FieldValues values;
  const char* description;

  constexpr std::uint32_t mask() const {
    return (width >= 32 ? 0xFFFFFFFFu : ((1u << width) - 1u)) << shift;
  }
};

/// Every field, grouped by register in the map's order, lowest bit first.
inline constexpr FieldInfo register_fields[] = {
    // clang-format off
    {Reg::status,  "BUSY",          0,                                1, Access::read_only,        FieldValues::none,          "an operation is in flight (the pin model only; lt, rtl and rtl-sync finish inside the access)"},
    {Reg::status,  "DONE",          1,                                1, Access::write_1_to_clear, FieldValues::none,          "results valid; write 1 to clear; drives done_irq"},
    {Reg::status,  "ERROR",         2,                                1, Access::write_1_to_clear, FieldValues::none,          "an access was refused; write 1 to clear (clears CAUSE and ERROR_ADDRESS too)"},
    {Reg::status,  "CAUSE",         status_bits::cause_shift,         8, Access::read_only,        FieldValues::error_cause,   "why the last access was refused (ErrorCause)"},
    {Reg::control, "START",         0,                                1, Access::self_clearing,    FieldValues::none,          "run one operation on COS, N, R, G, B; reads 0; any other bit is refused"},
    {Reg::config,  "NORMALISATION", config_bits::normalisation_shift, 2, Access::read_only,        FieldValues::normalisation, "what ROM 38 holds"},
    {Reg::config,  "SATURATION",    config_bits::saturation_shift,    1, Access::read_only,        FieldValues::saturation,    "what adder 8 does with a negative result"},
    {Reg::config,  "CONSTANTS",     config_bits::constants_shift,     2, Access::read_only,        FieldValues::constants,     "the constants on pins 19 and 20 and ROM 38's scale"},
    {Reg::config,  "COS_FRAC_BITS", config_bits::cos_frac_shift,      8, Access::read_only,        FieldValues::none,          "fraction bits of COS (U1.F): 1.0 is 1 << F"},
    {Reg::config,  "OUT_FRAC_BITS", config_bits::out_frac_shift,      8, Access::read_only,        FieldValues::none,          "fraction bits of OUT_R, OUT_G, OUT_B (signed)"},
    {Reg::config,  "RGB_BITS",      config_bits::rgb_bits_shift,      8, Access::read_only,        FieldValues::none,          "width of R, G, B: the largest is (1 << W) - 1"},
    // clang-format on
};
constexpr std::size_t field_count = sizeof register_fields / sizeof register_fields[0];

/// One value of an enumerated field.
struct FieldValue {
  std::string name;  ///< upper case, a C identifier (e.g. "DEVICE_ENERGY")
  std::uint32_t value;
  std::string description;
};

/// The values of an enumerated field, in ascending order, named after the C++ enum's
/// to_string (upper case, '-' as '_'); empty for FieldValues::none.
std::vector<FieldValue> field_values(FieldValues values);

namespace detail {
constexpr std::uint32_t fields_of(Reg reg) {
  std::uint32_t bits = 0;
  for (const FieldInfo& f : register_fields)
    if (f.reg == reg) bits |= f.mask();
  return bits;
}
constexpr std::uint32_t field_mask(Reg reg, int shift) {
  for (const FieldInfo& f : register_fields)
    if (f.reg == reg && f.shift == shift) return f.mask();
  return 0;
}
constexpr bool fields_are_consistent() {
  for (std::size_t i = 0; i < field_count; ++i) {
    const FieldInfo& f = register_fields[i];
    if (f.width < 1 || f.shift < 0 || f.shift + f.width > 32) return false;
    for (std::size_t j = 0; j < i; ++j)  // no two fields of one register overlap
      if (register_fields[j].reg == f.reg && (register_fields[j].mask() & f.mask()) != 0)
        return false;
  }
  return true;
}
}  // namespace detail

static_assert(detail::fields_are_consistent(), "register_fields: fields overlap or leave 32 bits");
static_assert(detail::field_mask(Reg::status, 0) == status_bits::busy &&
                  detail::field_mask(Reg::status, 1) == status_bits::done &&
                  detail::field_mask(Reg::status, 2) == status_bits::error &&
                  detail::field_mask(Reg::status, status_bits::cause_shift) == status_bits::cause_mask,
              "register_fields: STATUS differs from status_bits");
static_assert(detail::fields_of(Reg::control) == control_bits::defined &&
                  detail::field_mask(Reg::control, 0) == control_bits::start,
              "register_fields: CONTROL differs from control_bits");
static_assert(detail::field_mask(Reg::config, config_bits::normalisation_shift) >>
                      config_bits::normalisation_shift >=
                  static_cast<std::uint32_t>(Normalisation::device_energy) &&
                  detail::field_mask(Reg::config, config_bits::constants_shift) >>
                          config_bits::constants_shift >=
                      static_cast<std::uint32_t>(Constants::minimax) &&
                  detail::field_mask(Reg::config, config_bits::saturation_shift) >>
                          config_bits::saturation_shift >=
                      static_cast<std::uint32_t>(Saturation::literal) &&
                  detail::field_mask(Reg::config, config_bits::cos_frac_shift) != 0 &&
                  detail::field_mask(Reg::config, config_bits::out_frac_shift) != 0 &&
                  detail::field_mask(Reg::config, config_bits::rgb_bits_shift) != 0,
              "register_fields: a CONFIG field is missing or too narrow for its values");
static_assert((info(Reg::config).reset & ~detail::fields_of(Reg::config)) == 0,
              "register_fields: CONFIG's reset sets a bit no field holds");

}  // namespace specular
