/* A bare-metal RV32 program that shades pixels with the specular IP through the C driver
 * (firmware/include/specular/specular_driver.h), for a riscv-vp-like platform with the
 * IP's 32 KiB window at SPECULAR_BASE (docs/integration.md section 10). It polls
 * STATUS.DONE (no interrupt controller needed), leaves every result in RAM
 * (example_results, example_status: read them with the VP's debugger or memory dump)
 * and exits with 0 when the driver reported success, else the driver's error code's
 * magnitude. The expected bits are Core's: a host program on SpecularUnit::core computes
 * the same operands (tests/test_firmware_driver.cpp does so on the TLM targets). */
#include <stddef.h>
#include <stdint.h>

#include "specular/specular_driver.h"

#ifndef SPECULAR_BASE
#define SPECULAR_BASE 0x50000000u
#endif

#define PIXELS 8u

/* What the program leaves in RAM. */
volatile int32_t example_results[3u * PIXELS];  /* pins 24-26 of each pixel */
volatile int64_t example_reg9[2];               /* register 9 after each pass, one operation */
volatile int32_t example_status = 1;            /* 0 when done, else a specular_status */

static specular_dev dev;

int main(void);
int main(void) {
  /* One highlight row: cos from 1.0 down, n = 40, light (255, 200, 100). */
  static const uint32_t cos[PIXELS] = {65536u, 65400u, 65000u, 64500u, 63000u, 60000u, 50000u, 30000u};
  static const uint32_t rgb[3] = {255u, 200u, 100u};
  static int32_t out[3u * PIXELS];
  specular_operands one;
  specular_result result;
  size_t i;
  int status = specular_init(&dev, (uintptr_t)SPECULAR_BASE, NULL); /* volatile accesses */
  if (status == SPECULAR_OK) {
    one.cos = 64500u;
    one.n = 40u;
    one.rgb[0] = 255u;
    one.rgb[1] = 200u;
    one.rgb[2] = 100u;
    status = specular_compute(&dev, &one, &result);
  }
  if (status == SPECULAR_OK) {
    example_reg9[0] = result.reg9_pass1;
    example_reg9[1] = result.reg9_pass2;
    status = specular_shade(&dev, 40u, rgb, cos, PIXELS, out);
  }
  if (status == SPECULAR_OK)
    for (i = 0; i < 3u * PIXELS; ++i) example_results[i] = out[i];
  example_status = status;
  return status < 0 ? -status : status;
}
