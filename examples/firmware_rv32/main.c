/* A bare-metal RV32 program that shades pixels with the specular IP through the C driver
 * (firmware/include/specular/specular_driver.h), for a riscv-vp-like platform with the
 * IP's 32 KiB window at SPECULAR_BASE (docs/integration.md section 10). It leaves every
 * result in RAM (example_results, example_reg9, example_status: read them with the VP's
 * debugger or a memory dump) and exits with 0 when the driver reported success, else the
 * magnitude of the driver's error code. The expected bits are Core's: a host program on
 * SpecularUnit::core computes them for the same operands.
 *
 * Default: the driver polls STATUS.DONE (no interrupt wiring needed). Built with
 * -DEXAMPLE_WAIT_IRQ it waits by interrupt instead: done_irq must reach the hart's machine
 * external interrupt (riscv-vp: on_done_irq -> trigger/clear_external_interrupt, section
 * 10); the trap handler calls specular_irq_handler (acknowledge, set the flag) and the
 * driver sleeps in wfi between operations. */
#include <stddef.h>
#include <stdint.h>

#include "specular/specular_driver.h"

#ifndef SPECULAR_BASE
#define SPECULAR_BASE 0x50000000u
#endif

#define PIXELS 8u
#define MCAUSE_MACHINE_EXTERNAL 0x8000000Bu

/* What the program leaves in RAM. */
volatile int32_t example_results[3u * PIXELS];  /* pins 24-26 of each pixel */
volatile int64_t example_reg9[2];               /* register 9 after each pass, one operation */
volatile int32_t example_status = 1;            /* 0 when done, else a specular_status */
volatile uint32_t example_interrupts;           /* done interrupts taken */

static specular_dev dev;

/* startup.S */
void example_halt(void);
void example_interrupts_on(void);
void example_sleep_unless(volatile uint32_t* flag);

/* Called by startup.S's trap entry for every trap. */
void example_trap(uint32_t mcause);
void example_trap(uint32_t mcause) {
  if (mcause == MCAUSE_MACHINE_EXTERNAL) {
    ++example_interrupts;
    specular_irq_handler(&dev);  /* acknowledges (the level falls) and sets dev.irq_pending */
    return;
  }
  example_halt();  /* an exception (or an exit call the platform does not take) */
}

#ifdef EXAMPLE_WAIT_IRQ
/* The driver's idle hook: sleep until the interrupt (the flag is tested with interrupts
 * masked, in example_sleep_unless). */
static void sleep_until_interrupt(void* context) {
  example_sleep_unless(&((specular_dev*)context)->irq_pending);
}
#endif

int main(void);
int main(void) {
  /* One highlight row: cos from 1.0 down, n = 40, light (255, 200, 100). */
  static const uint32_t cos[PIXELS] = {65536u, 65400u, 65000u, 64500u, 63000u, 60000u, 50000u, 30000u};
  static const uint32_t rgb[3] = {255u, 200u, 100u};
  static int32_t out[3u * PIXELS];
  specular_operands one;
  specular_result result;
  size_t i;
  int status;
#ifdef EXAMPLE_WAIT_IRQ
  specular_bus bus = {NULL, NULL, NULL, NULL, sleep_until_interrupt, NULL};
  bus.context = &dev;  /* read32/write32 NULL: volatile accesses, only the idle hook set */
  status = specular_init(&dev, (uintptr_t)SPECULAR_BASE, &bus);
  dev.wait_mode = SPECULAR_WAIT_IRQ;
  dev.poll_limit = 0u;  /* wfi wakes on the interrupt: no need to count */
  example_interrupts_on();
#else
  status = specular_init(&dev, (uintptr_t)SPECULAR_BASE, NULL); /* volatile accesses, polling */
#endif
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
