// The firmware C header (firmware/include/specular/specular_regs.h, issue 35) against the
// C++ register map, the truth: every register's offset, access, reset value and size,
// every field's shift, width, mask and access, every enumerated value, the window sizes,
// the operand ranges and the interrupt's macros. The C names are listed here by hand
// (one line per register, field and value), so a register or value the generator
// dropped or renamed fails to compile, and one it got wrong fails below; the counts
// make a register or value missing from these lists fail too.
//
// (firmware_header_current checks that the committed header is the generated one.)
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>

#include "specular/specular_regs.h"
#include "specular/format.h"
#include "specular/rom38_banks.h"
#include "specular/tlm/register_fields.h"
#include "specular/tlm/register_map.h"

namespace specular {
namespace {

struct CRegister {
  Reg reg;
  const char* name;
  std::uint32_t offset, access, reset, words;
};
#define REG(NAME, reg) {Reg::reg, #NAME, SPECULAR_##NAME##_OFFSET, SPECULAR_##NAME##_ACCESS, SPECULAR_##NAME##_RESET, 1u}
#define WINDOW(NAME, reg) \
  {Reg::reg, #NAME, SPECULAR_##NAME##_OFFSET, SPECULAR_##NAME##_ACCESS, SPECULAR_##NAME##_RESET, SPECULAR_##NAME##_WORDS}
const CRegister c_registers[] = {
    REG(ID, id), REG(VERSION, version), REG(CONFIG, config), REG(STATUS, status),
    REG(CONTROL, control), REG(BATCH_CAPACITY, batch_capacity), REG(ERROR_ADDRESS, error_address),
    REG(COS, cos), REG(N, n), REG(R, r), REG(G, g), REG(B, b), REG(OUT_R, out_r),
    REG(OUT_G, out_g), REG(OUT_B, out_b), REG(REG1, reg1), REG(REG9_PASS1_LO, reg9_pass1_lo),
    REG(REG9_PASS1_HI, reg9_pass1_hi), REG(REG9_PASS2_LO, reg9_pass2_lo),
    REG(REG9_PASS2_HI, reg9_pass2_hi), REG(ROM38_K, rom38_k), REG(NORM39, norm39),
    REG(PIN19_H, pin19_h), REG(PIN20_A, pin20_a), WINDOW(OPERANDS, operands),
    WINDOW(RESULTS, results), WINDOW(BATCH_COS, batch_cos), WINDOW(BATCH_OUT, batch_out),
};
#undef REG
#undef WINDOW

/// The C access code the header gives each C++ access kind (the header's own legend).
std::uint32_t c_access(Access access) {
  switch (access) {
    case Access::read_only: return SPECULAR_ACCESS_RO;
    case Access::read_write: return SPECULAR_ACCESS_RW;
    case Access::write_1_to_clear: return SPECULAR_ACCESS_W1C;
    case Access::self_clearing: return SPECULAR_ACCESS_WSC;
  }
  return 0xFFFFFFFFu;
}

TEST(FirmwareHeader, AccessCodesAreDistinct) {
  const std::set<std::uint32_t> codes{SPECULAR_ACCESS_RO, SPECULAR_ACCESS_RW, SPECULAR_ACCESS_W1C,
                                      SPECULAR_ACCESS_WSC};
  EXPECT_EQ(codes.size(), 4u);
}

TEST(FirmwareHeader, EveryRegisterHasTheMapsOffsetAccessResetAndSize) {
  ASSERT_EQ(sizeof c_registers / sizeof c_registers[0], register_count);
  ASSERT_EQ(SPECULAR_REGISTER_COUNT, register_count);
  std::set<Reg> seen;
  for (const CRegister& c : c_registers) {
    const RegisterInfo& row = info(c.reg);
    SCOPED_TRACE(row.name);
    EXPECT_TRUE(seen.insert(c.reg).second) << "listed twice";
    EXPECT_EQ(std::string(c.name), row.name);
    EXPECT_EQ(c.offset, row.offset);
    EXPECT_EQ(c.access, c_access(row.access));
    EXPECT_EQ(c.reset, row.reset);
    EXPECT_EQ(c.words, row.words);
  }
  EXPECT_EQ(SPECULAR_OPERANDS_SIZE, 4 * info(Reg::operands).words);
  EXPECT_EQ(SPECULAR_RESULTS_SIZE, 4 * info(Reg::results).words);
  EXPECT_EQ(SPECULAR_BATCH_COS_SIZE, 4 * info(Reg::batch_cos).words);
  EXPECT_EQ(SPECULAR_BATCH_OUT_SIZE, 4 * info(Reg::batch_out).words);
}

TEST(FirmwareHeader, TheIpsIdentityWindowsAndRangesAreTheMaps) {
  EXPECT_EQ(SPECULAR_DEVICE_ID, device_id);
  EXPECT_EQ(SPECULAR_MAP_VERSION, map_version);
  EXPECT_EQ(SPECULAR_MAP_VERSION_MAJOR, map_version >> 16);
  EXPECT_EQ(SPECULAR_MAP_SIZE, map_size);
  EXPECT_EQ(SPECULAR_BATCH_CAPACITY, batch_capacity);
  EXPECT_EQ(SPECULAR_BATCH_COS_WORDS, batch_capacity);
  EXPECT_EQ(SPECULAR_BATCH_OUT_WORDS, 3 * batch_capacity);
  EXPECT_EQ(SPECULAR_BATCH_OUT_WORDS_PER_OPERATION, 3u);
  EXPECT_EQ(SPECULAR_N_MIN, n_min);
  EXPECT_EQ(SPECULAR_N_MAX, n_max);
  const Formats defaults{};
  EXPECT_EQ(SPECULAR_COS_MAX_DEFAULT, static_cast<std::uint32_t>(defaults.cos.one()));
  EXPECT_EQ(SPECULAR_RGB_MAX_DEFAULT, static_cast<std::uint32_t>(defaults.rgb.max_code()));
  // OPERANDS and RESULTS: which register each word is.
  const std::uint32_t operand_words_c[] = {SPECULAR_OPERANDS_COS_WORD, SPECULAR_OPERANDS_N_WORD,
                                           SPECULAR_OPERANDS_R_WORD,   SPECULAR_OPERANDS_G_WORD,
                                           SPECULAR_OPERANDS_B_WORD,   SPECULAR_OPERANDS_CONTROL_WORD};
  const Reg operand_regs[] = {Reg::cos, Reg::n, Reg::r, Reg::g, Reg::b, Reg::control};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(operand_register(operand_words_c[i]), operand_regs[i]) << i;
  EXPECT_EQ(result_register(SPECULAR_RESULTS_OUT_R_WORD), Reg::out_r);
  EXPECT_EQ(result_register(SPECULAR_RESULTS_OUT_G_WORD), Reg::out_g);
  EXPECT_EQ(result_register(SPECULAR_RESULTS_OUT_B_WORD), Reg::out_b);
}

struct CField {
  Reg reg;
  const char* name;
  std::uint32_t shift, width, mask, access;
};
#define FIELD(REG, NAME, reg)                                                          \
  {Reg::reg, #NAME, SPECULAR_##REG##_##NAME##_SHIFT, SPECULAR_##REG##_##NAME##_WIDTH, \
   SPECULAR_##REG##_##NAME##_MASK, SPECULAR_##REG##_##NAME##_ACCESS}
const CField c_fields[] = {
    FIELD(VERSION, MINOR, version),       FIELD(VERSION, MAJOR, version),
    FIELD(CONFIG, NORMALISATION, config), FIELD(CONFIG, SATURATION, config),
    FIELD(CONFIG, CONSTANTS, config),     FIELD(CONFIG, COS_FRAC_BITS, config),
    FIELD(CONFIG, OUT_FRAC_BITS, config), FIELD(CONFIG, RGB_BITS, config),
    FIELD(STATUS, BUSY, status),          FIELD(STATUS, DONE, status),
    FIELD(STATUS, ERROR, status),         FIELD(STATUS, CAUSE, status),
    FIELD(CONTROL, START, control),
};
#undef FIELD

TEST(FirmwareHeader, EveryFieldHasTheMapsShiftWidthMaskAndAccess) {
  ASSERT_EQ(sizeof c_fields / sizeof c_fields[0], field_count);
  for (std::size_t i = 0; i < field_count; ++i) {
    const FieldInfo& f = register_fields[i];
    const CField& c = c_fields[i];
    SCOPED_TRACE(std::string(info(f.reg).name) + "." + f.name);
    EXPECT_EQ(c.reg, f.reg);
    EXPECT_EQ(std::string(c.name), f.name);
    EXPECT_EQ(c.shift, static_cast<std::uint32_t>(f.shift));
    EXPECT_EQ(c.width, static_cast<std::uint32_t>(f.width));
    EXPECT_EQ(c.mask, ((1ull << f.width) - 1) << f.shift);
    EXPECT_EQ(c.access, c_access(f.access));
  }
}

// The register map's own constants (status_bits, control_bits, config_bits), not the
// field table: what the target decodes.
TEST(FirmwareHeader, FieldsAreWhereTheTargetPutsThem) {
  EXPECT_EQ(SPECULAR_STATUS_BUSY_MASK, status_bits::busy);
  EXPECT_EQ(SPECULAR_STATUS_DONE_MASK, status_bits::done);
  EXPECT_EQ(SPECULAR_STATUS_ERROR_MASK, status_bits::error);
  EXPECT_EQ(SPECULAR_STATUS_CAUSE_MASK, status_bits::cause_mask);
  EXPECT_EQ(SPECULAR_STATUS_CAUSE_SHIFT, static_cast<std::uint32_t>(status_bits::cause_shift));
  EXPECT_EQ(SPECULAR_CONTROL_START_MASK, control_bits::start);
  EXPECT_EQ(SPECULAR_CONTROL_START_MASK, control_bits::defined);
  EXPECT_EQ(SPECULAR_CONFIG_NORMALISATION_SHIFT, static_cast<std::uint32_t>(config_bits::normalisation_shift));
  EXPECT_EQ(SPECULAR_CONFIG_SATURATION_SHIFT, static_cast<std::uint32_t>(config_bits::saturation_shift));
  EXPECT_EQ(SPECULAR_CONFIG_CONSTANTS_SHIFT, static_cast<std::uint32_t>(config_bits::constants_shift));
  EXPECT_EQ(SPECULAR_CONFIG_COS_FRAC_BITS_SHIFT, static_cast<std::uint32_t>(config_bits::cos_frac_shift));
  EXPECT_EQ(SPECULAR_CONFIG_OUT_FRAC_BITS_SHIFT, static_cast<std::uint32_t>(config_bits::out_frac_shift));
  EXPECT_EQ(SPECULAR_CONFIG_RGB_BITS_SHIFT, static_cast<std::uint32_t>(config_bits::rgb_bits_shift));
  // Every configuration's word, taken apart with the header's helpers.
  for (Normalisation norm : every_normalisation)
    for (Constants constants : every_constants)
      for (Saturation sat : {Saturation::clamp, Saturation::literal}) {
        const std::uint32_t word = config_word(norm, sat, 15, 12, 7, constants);
        EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_CONFIG_NORMALISATION, word), static_cast<std::uint32_t>(norm));
        EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_CONFIG_SATURATION, word), static_cast<std::uint32_t>(sat));
        EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_CONFIG_CONSTANTS, word), static_cast<std::uint32_t>(constants));
        EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_CONFIG_COS_FRAC_BITS, word), 15u);
        EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_CONFIG_OUT_FRAC_BITS, word), 12u);
        EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_CONFIG_RGB_BITS, word), 7u);
        EXPECT_EQ(SPECULAR_FIELD_PREP(SPECULAR_CONFIG_NORMALISATION, static_cast<std::uint32_t>(norm)) |
                      SPECULAR_FIELD_PREP(SPECULAR_CONFIG_SATURATION, static_cast<std::uint32_t>(sat)) |
                      SPECULAR_FIELD_PREP(SPECULAR_CONFIG_CONSTANTS, static_cast<std::uint32_t>(constants)) |
                      SPECULAR_FIELD_PREP(SPECULAR_CONFIG_COS_FRAC_BITS, 15u) |
                      SPECULAR_FIELD_PREP(SPECULAR_CONFIG_OUT_FRAC_BITS, 12u) |
                      SPECULAR_FIELD_PREP(SPECULAR_CONFIG_RGB_BITS, 7u),
                  word);
      }
  EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_STATUS_CAUSE, 0x00000704u), 7u);
  // VERSION is (major << 16) | minor: 0x00010001 is 1.1.
  EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_VERSION_MAJOR, 0x00030002u), 3u);
  EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_VERSION_MINOR, 0x00030002u), 2u);
  EXPECT_EQ(SPECULAR_FIELD_GET(SPECULAR_VERSION_MAJOR, map_version), SPECULAR_MAP_VERSION_MAJOR);
}

TEST(FirmwareHeader, EveryEnumeratedValueIsTheCppEnumsNumber) {
  const std::uint32_t causes[] = {
      SPECULAR_STATUS_CAUSE_NONE,          SPECULAR_STATUS_CAUSE_COS_OUT_OF_RANGE,
      SPECULAR_STATUS_CAUSE_N_OUT_OF_RANGE, SPECULAR_STATUS_CAUSE_RGB_OUT_OF_RANGE,
      SPECULAR_STATUS_CAUSE_READ_ONLY,     SPECULAR_STATUS_CAUSE_RESERVED_BITS,
      SPECULAR_STATUS_CAUSE_BUSY,          SPECULAR_STATUS_CAUSE_ADDRESS,
      SPECULAR_STATUS_CAUSE_BURST,         SPECULAR_STATUS_CAUSE_BYTE_ENABLE,
      SPECULAR_STATUS_CAUSE_COMMAND};
  const ErrorCause cpp_causes[] = {
      ErrorCause::none,          ErrorCause::cos_out_of_range, ErrorCause::n_out_of_range,
      ErrorCause::rgb_out_of_range, ErrorCause::read_only,     ErrorCause::reserved_bits,
      ErrorCause::busy,          ErrorCause::address,          ErrorCause::burst,
      ErrorCause::byte_enable,   ErrorCause::command};
  ASSERT_EQ(SPECULAR_STATUS_CAUSE_COUNT, error_cause_count);
  ASSERT_EQ(sizeof causes / sizeof causes[0], error_cause_count);
  for (std::size_t i = 0; i < error_cause_count; ++i) {
    EXPECT_EQ(causes[i], static_cast<std::uint32_t>(cpp_causes[i])) << to_string(cpp_causes[i]);
    EXPECT_LE(causes[i], SPECULAR_STATUS_CAUSE_MASK >> SPECULAR_STATUS_CAUSE_SHIFT);
  }

  EXPECT_EQ(SPECULAR_CONFIG_NORMALISATION_COUNT, std::size(every_normalisation));
  EXPECT_EQ(SPECULAR_CONFIG_NORMALISATION_PATENT, static_cast<std::uint32_t>(Normalisation::patent));
  EXPECT_EQ(SPECULAR_CONFIG_NORMALISATION_ENERGY, static_cast<std::uint32_t>(Normalisation::energy));
  EXPECT_EQ(SPECULAR_CONFIG_NORMALISATION_NONE, static_cast<std::uint32_t>(Normalisation::none));
  EXPECT_EQ(SPECULAR_CONFIG_NORMALISATION_DEVICE_ENERGY,
            static_cast<std::uint32_t>(Normalisation::device_energy));
  EXPECT_EQ(SPECULAR_CONFIG_SATURATION_COUNT, 2u);
  EXPECT_EQ(SPECULAR_CONFIG_SATURATION_CLAMP, static_cast<std::uint32_t>(Saturation::clamp));
  EXPECT_EQ(SPECULAR_CONFIG_SATURATION_LITERAL, static_cast<std::uint32_t>(Saturation::literal));
  EXPECT_EQ(SPECULAR_CONFIG_CONSTANTS_COUNT, std::size(every_constants));
  EXPECT_EQ(SPECULAR_CONFIG_CONSTANTS_PATENT, static_cast<std::uint32_t>(Constants::patent));
  EXPECT_EQ(SPECULAR_CONFIG_CONSTANTS_MINIMAX_HALF, static_cast<std::uint32_t>(Constants::minimax_half));
  EXPECT_EQ(SPECULAR_CONFIG_CONSTANTS_MINIMAX, static_cast<std::uint32_t>(Constants::minimax));
}

TEST(FirmwareHeader, TheInterruptIsStatusDoneAndIsAcknowledgedByWritingIt) {
  EXPECT_EQ(SPECULAR_IRQ_LEVEL_SENSITIVE, 1u);
  EXPECT_EQ(SPECULAR_IRQ_STATUS_MASK, status_bits::done);
  EXPECT_EQ(SPECULAR_IRQ_ACK_OFFSET, offset_of(Reg::status));
  EXPECT_EQ(SPECULAR_IRQ_ACK_VALUE, status_bits::done);
  EXPECT_EQ(info(Reg::status).access, Access::write_1_to_clear);
}

}  // namespace
}  // namespace specular
