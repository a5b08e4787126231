/* Compiled by the firmware_compile_* tests (tests/firmware/CMakeLists.txt) with each
 * firmware toolchain, as C99 and as C++, under -Wall -Wextra -Wpedantic -Werror
 * -ffreestanding: the generated register header and the driver's header as a firmware
 * build includes them. The checks below are compile-time relations between the header's
 * own numbers (a failed one is a negative array size: a compile error on every toolchain);
 * the values themselves are checked against the C++ map by tests/test_firmware_regs.cpp. */
#include "specular/specular_regs.h"
#include "specular/specular_driver.h"

#define FIRMWARE_CHECK(name, condition) typedef char firmware_check_##name[(condition) ? 1 : -1]

FIRMWARE_CHECK(batch_out_holds_three_words_per_cos,
               SPECULAR_BATCH_OUT_WORDS == SPECULAR_BATCH_OUT_WORDS_PER_OPERATION * SPECULAR_BATCH_COS_WORDS);
FIRMWARE_CHECK(batch_cos_holds_the_capacity, SPECULAR_BATCH_COS_WORDS == SPECULAR_BATCH_CAPACITY);
FIRMWARE_CHECK(windows_inside_the_map,
               SPECULAR_BATCH_OUT_OFFSET + SPECULAR_BATCH_OUT_SIZE <= SPECULAR_MAP_SIZE);
FIRMWARE_CHECK(status_fields_apart, (SPECULAR_STATUS_DONE_MASK & SPECULAR_STATUS_ERROR_MASK) == 0u);
FIRMWARE_CHECK(irq_is_done, SPECULAR_IRQ_ACK_VALUE == SPECULAR_STATUS_DONE_MASK);
FIRMWARE_CHECK(field_get, SPECULAR_FIELD_GET(SPECULAR_CONFIG_RGB_BITS, SPECULAR_CONFIG_RESET) == 8u);
FIRMWARE_CHECK(field_prep,
               SPECULAR_FIELD_PREP(SPECULAR_STATUS_CAUSE, SPECULAR_STATUS_CAUSE_BUSY) == 0x600u);

/* The driver's types as firmware uses them. */
uint32_t firmware_check_cause(const specular_dev* dev);
uint32_t firmware_check_cause(const specular_dev* dev) {
  return dev->cause == SPECULAR_STATUS_CAUSE_N_OUT_OF_RANGE ? (uint32_t)SPECULAR_ERR_N : 0u;
}
