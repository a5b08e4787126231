/* The installed driver on its default accessors (volatile loads and stores at base +
 * offset), on the host: a word array stands in for the IP's window, holding what the IP
 * would show after an operation (ID, VERSION, CONFIG of the default device, STATUS.DONE,
 * the pins). Exit 0 when the driver read them back through the volatile path, wrote
 * START and acknowledged; the numbers are the header's own, so any offset the driver got
 * wrong reads a 0 or misses a write. */
#include <stdint.h>

#include "specular/specular_driver.h"

static uint32_t window[SPECULAR_MAP_SIZE / 4u];

#define WORD(offset) window[(offset) / 4u]

int main(void);
int main(void) {
  specular_dev dev;
  specular_operands in;
  specular_result out;
  int status;
  WORD(SPECULAR_ID_OFFSET) = SPECULAR_DEVICE_ID;
  WORD(SPECULAR_VERSION_OFFSET) = SPECULAR_MAP_VERSION;
  WORD(SPECULAR_CONFIG_OFFSET) = SPECULAR_CONFIG_RESET;
  status = specular_init(&dev, (uintptr_t)window, 0);
  if (status != SPECULAR_OK) return 10 - status;
  if (dev.cos_max != SPECULAR_COS_MAX_DEFAULT || dev.rgb_max != SPECULAR_RGB_MAX_DEFAULT) return 20;
  /* The operation "ended"; CAUSE bits without ERROR: the acknowledge must overwrite them. */
  WORD(SPECULAR_STATUS_OFFSET) = SPECULAR_STATUS_DONE_MASK | SPECULAR_FIELD_PREP(SPECULAR_STATUS_CAUSE, 7u);
  WORD(SPECULAR_OUT_R_OFFSET) = 0x11u;
  WORD(SPECULAR_OUT_G_OFFSET) = 0x22u;
  WORD(SPECULAR_OUT_B_OFFSET) = 0xFFFFFFFFu; /* -1: sign kept */
  WORD(SPECULAR_REG9_PASS2_LO_OFFSET) = 0x00400000u;
  in.cos = 65536u;
  in.n = 40u;
  in.rgb[0] = 255u;
  in.rgb[1] = 200u;
  in.rgb[2] = 100u;
  status = specular_compute(&dev, &in, &out);
  if (status != SPECULAR_OK) return 30 - status;
  if (out.out[0] != 0x11 || out.out[1] != 0x22 || out.out[2] != -1 || out.reg9_pass2 != 0x400000) return 40;
  if (WORD(SPECULAR_N_OFFSET) != 40u || WORD(SPECULAR_COS_OFFSET) != 65536u || WORD(SPECULAR_B_OFFSET) != 100u)
    return 50;
  if (WORD(SPECULAR_CONTROL_OFFSET) != SPECULAR_CONTROL_START_MASK) return 60;
  if (WORD(SPECULAR_STATUS_OFFSET) != SPECULAR_IRQ_ACK_VALUE) return 70; /* the acknowledge */
  return 0;
}
