/* A bare-metal RV32 program that shades pixels with the specular IP through the C driver
 * (firmware/include/specular/specular_driver.h) and checks every result itself, for a
 * riscv-vp-like platform with the IP's 32 KiB window at SPECULAR_BASE (docs/firmware.md,
 * docs/integration/riscv_vp.md).
 *
 * What it does, in order, reporting each step on the console (example_console_write):
 *   1. binds the driver (ID, VERSION, CONFIG);
 *   2. makes one access the IP refuses (N = 1001): on a platform that turns the error
 *      response into a store access fault the trap handler skips the store; either way
 *      specular_check_error must then report the refusal with cause N_OUT_OF_RANGE;
 *   3. one operation, polled: pins 24-26 and register 9 after each pass;
 *   4. a row of EXAMPLE_PIXELS pixels through the batch windows (polled, or by interrupt
 *      in the interrupt builds).
 * Every result is compared with example_expected.h, which the host computed with Core
 * (the bit-accurate core) at build time; the first difference is named and ends the
 * program. Steps 3 and 4 wait under a watchdog: no STATUS.DONE (polled) or no done
 * interrupt within EXAMPLE_WATCHDOG_TICKS of the CLINT's mtime prints a FAIL line naming
 * what it waited on (the PLIC's source and context, or the hart's external interrupt)
 * and exits. Exit status: 0 all equal; 1-9 the driver's error (minus its code); 10 the
 * refusal not reported; 20 a result differs; 30 the watchdog fired; 40 an unexpected trap.
 *
 * Build options (-D; examples/firmware_rv32/example_options.cmake checks them):
 *   SPECULAR_BASE=addr       the IP's base (default 0x50000000)
 *   EXAMPLE_WAIT_IRQ         the row waits by interrupt, through a PLIC (SiFive/FE310
 *                            layout): EXAMPLE_PLIC_BASE (default 0x0C000000),
 *                            EXAMPLE_PLIC_SOURCE (done_irq's source, 1..1023, default 1),
 *                            EXAMPLE_PLIC_CONTEXT (default 0: hart 0 machine mode),
 *                            EXAMPLE_PLIC_ENABLE_STRIDE, EXAMPLE_PLIC_CONTEXT_STRIDE (bytes
 *                            per context of enable bits and of threshold/claim: SiFive's
 *                            0x80 and 0x1000 by default; riscv-vp's FE310_PLIC packs them,
 *                            docs/firmware.md)
 *   EXAMPLE_IRQ_DIRECT       with EXAMPLE_WAIT_IRQ: done_irq wired straight to the hart's
 *                            machine external interrupt, no PLIC
 *   EXAMPLE_CLINT_BASE=addr  the CLINT (SiFive layout: mtimecmp of hart 0 at +0x4000,
 *                            mtime at +0xBFF8) whose mtime bounds each wait and whose
 *                            timer interrupt wakes a wfi that nothing else would (default
 *                            0x02000000, riscv-vp's and FE310's)
 *   EXAMPLE_WATCHDOG_TICKS=n the bound, in mtime ticks (default 65536: 65.5 ms of
 *                            simulated time at riscv-vp's 1 MHz CLINT, 2 s at the
 *                            32.768 kHz of FE310's and riscv-vp tiny32's); 0: no watchdog
 *                            and no CLINT access
 *   EXAMPLE_UART_BASE=addr   the console is a byte-wide transmit register at addr
 *                            (default: the write system call, which riscv-vp's
 *                            --intercept-syscalls takes)
 *   EXAMPLE_ENERGY_COUNTER=addr  the platform's energy counter (SpecularEnergyCounter,
 *                            specular/tlm/energy_counter.h; docs/energy.md): read before
 *                            and after the row, whose energy per pixel and in all the
 *                            program then prints (default: none, nothing read)
 *   EXAMPLE_BUS              the driver's accessors are the platform's, from
 *                            example_platform_bus() (default: none, volatile loads and
 *                            stores); the host test (tests/test_firmware_example_*.cpp)
 *                            routes them to a TLM target */
#include <stddef.h>
#include <stdint.h>

#include "specular/specular_driver.h"
#include "example_expected.h"
#include "example_operands.h"

#ifndef SPECULAR_BASE
#define SPECULAR_BASE 0x50000000u
#endif
#ifndef EXAMPLE_PLIC_BASE
#define EXAMPLE_PLIC_BASE 0x0C000000u
#endif
#ifndef EXAMPLE_PLIC_SOURCE
#define EXAMPLE_PLIC_SOURCE 1u
#endif
#ifndef EXAMPLE_PLIC_CONTEXT
#define EXAMPLE_PLIC_CONTEXT 0u
#endif
#ifndef EXAMPLE_PLIC_ENABLE_STRIDE
#define EXAMPLE_PLIC_ENABLE_STRIDE 0x80u
#endif
#ifndef EXAMPLE_PLIC_CONTEXT_STRIDE
#define EXAMPLE_PLIC_CONTEXT_STRIDE 0x1000u
#endif
#ifndef EXAMPLE_CLINT_BASE
#define EXAMPLE_CLINT_BASE 0x02000000u
#endif
#ifndef EXAMPLE_WATCHDOG_TICKS
#define EXAMPLE_WATCHDOG_TICKS 65536u
#endif
#if EXAMPLE_PLIC_SOURCE < 1 || EXAMPLE_PLIC_SOURCE > 1023
#error "EXAMPLE_PLIC_SOURCE: a PLIC's sources are 1..1023"
#endif
#if EXAMPLE_PLIC_CONTEXT > 15871
#error "EXAMPLE_PLIC_CONTEXT: a PLIC's contexts are 0..15871"
#endif
#if EXAMPLE_PLIC_ENABLE_STRIDE < 4 * (EXAMPLE_PLIC_SOURCE / 32 + 1) || EXAMPLE_PLIC_ENABLE_STRIDE > 0x80 || \
    EXAMPLE_PLIC_ENABLE_STRIDE % 4 != 0
#error "EXAMPLE_PLIC_ENABLE_STRIDE: 4 bytes per 32 sources (up to the source's word) .. 0x80, a multiple of 4"
#endif
#if EXAMPLE_PLIC_CONTEXT_STRIDE < 8 || EXAMPLE_PLIC_CONTEXT_STRIDE > 0x1000 || EXAMPLE_PLIC_CONTEXT_STRIDE % 4 != 0
#error "EXAMPLE_PLIC_CONTEXT_STRIDE: 8 (threshold and claim) .. 0x1000, a multiple of 4"
#endif

#define MCAUSE_MACHINE_EXTERNAL 0x8000000Bu
#define MCAUSE_MACHINE_TIMER 0x80000007u
#define MCAUSE_LOAD_ACCESS_FAULT 5u
#define MCAUSE_STORE_ACCESS_FAULT 7u
#define MCAUSE_ECALL_FROM_M 11u
#define MCAUSE_LOAD_PAGE_FAULT 13u   /* riscv-vp reports a failed bus transaction so */
#define MCAUSE_STORE_PAGE_FAULT 15u

#define EXIT_REFUSAL_NOT_REPORTED 10
#define EXIT_RESULT_DIFFERS 20
#define EXIT_WATCHDOG 30
#define EXIT_UNEXPECTED_TRAP 40

/* What the program leaves in RAM too (for a debugger or a memory dump). */
volatile int32_t example_results[3u * EXAMPLE_PIXELS]; /* pins 24-26 of each pixel */
volatile int64_t example_reg9[2];                      /* register 9 after each pass, one operation */
volatile int32_t example_status = 1;                   /* the exit status, once known */
volatile uint32_t example_interrupts;                  /* done interrupts taken */
volatile uint32_t example_spurious_interrupts;         /* ... and taken with STATUS.DONE clear */
volatile uint32_t example_unclaimed_interrupts;        /* external ones the PLIC had no done_irq for */
volatile uint32_t example_bus_faults;                  /* load/store faults skipped */
volatile uint32_t example_last_fault_cause;            /* mcause of the last one */
volatile uint32_t example_last_fault_address;          /* mtval of the last one */

static specular_dev dev;

#ifdef EXAMPLE_ENERGY_COUNTER
/* The platform's energy counter: 64-bit values read low word first (the read latches
 * the high word). */
static uint64_t energy_counter_read(uint32_t low_offset) {
  volatile uint32_t* const counter = (volatile uint32_t*)(uintptr_t)(EXAMPLE_ENERGY_COUNTER + low_offset);
  const uint32_t low = counter[0];
  return ((uint64_t)counter[1] << 32) | low;
}
#define ENERGY_COUNTER_PJ 0x0u
#define ENERGY_COUNTER_OPERATIONS 0x8u
#endif

#ifdef EXAMPLE_BUS
const specular_bus* example_platform_bus(void);
#endif

/* startup.S */
void example_halt(void);
void example_exit(int status);
void example_interrupts_on(void);
void example_timer_interrupt_on(void);
void example_timer_interrupt_off(void);
void example_sleep_unless(volatile uint32_t* flag);
void example_console_write(const char* text, size_t length);

/* ---- console: a short report ---------------------------------------------------- */

#ifdef EXAMPLE_UART_BASE
void example_console_write(const char* text, size_t length) {
  size_t i;
  for (i = 0; i < length; ++i) *(volatile uint8_t*)(uintptr_t)EXAMPLE_UART_BASE = (uint8_t)text[i];
}
#endif

static void say(const char* text) {
  size_t length = 0;
  while (text[length] != '\0') ++length;
  example_console_write(text, length);
}

static void say_signed(int64_t value) {
  char digits[24];
  size_t at = sizeof digits;
  uint64_t magnitude = value < 0 ? (uint64_t)0 - (uint64_t)value : (uint64_t)value;
  do {
    digits[--at] = (char)('0' + (int)(magnitude % 10u));
    magnitude /= 10u;
  } while (magnitude != 0u);
  if (value < 0) digits[--at] = '-';
  example_console_write(digits + at, sizeof digits - at);
}

static void say_hex(uint32_t value) {
  char digits[10];
  int i;
  digits[0] = '0';
  digits[1] = 'x';
  for (i = 0; i < 8; ++i) digits[2 + i] = "0123456789abcdef"[(value >> (28 - 4 * i)) & 0xFu];
  example_console_write(digits, sizeof digits);
}

static int driver_failed(const char* step, int status) {
  say("FAIL: ");
  say(step);
  say(": ");
  say(specular_strerror(status));
  say("\n");
  return status < 0 ? -status : status;
}

/* Compares one result with Core's; names the first difference. */
static int same(const char* what, int64_t index, const char* part, int64_t got, int64_t expected) {
  if (got == expected) return 1;
  say("FAIL: ");
  say(what);
  if (index >= 0) {
    say(" ");
    say_signed(index);
  }
  say(" ");
  say(part);
  say(": IP ");
  say_signed(got);
  say(", Core ");
  say_signed(expected);
  say("\n");
  return 0;
}

/* ---- the watchdog ---------------------------------------------------------------- */

/* Each wait (steps 3 and 4) is bounded by the CLINT's mtime: polling checks it in the
 * driver's idle hook; an interrupt wait also arms the CLINT's timer, because a wfi that
 * no done interrupt ends would never return to check anything. An external interrupt
 * that brings no done (the line reaching the hart but not the PLIC: re-entered for ever)
 * checks it too, as it starves the timer's lower-priority interrupt. */
#if EXAMPLE_WATCHDOG_TICKS != 0
#define CLINT_MTIMECMP 0x4000u /* hart 0's; SiFive's layout, as FE310's and riscv-vp's */
#define CLINT_MTIME 0xBFF8u

static volatile uint32_t* clint(uint32_t offset) {
  return (volatile uint32_t*)((uintptr_t)EXAMPLE_CLINT_BASE + offset);
}

static uint64_t mtime_now(void) {
  uint32_t high, low;
  do { /* the high word again: the low one may have wrapped between the two reads */
    high = *clint(CLINT_MTIME + 4u);
    low = *clint(CLINT_MTIME);
  } while (high != *clint(CLINT_MTIME + 4u));
  return (uint64_t)high << 32 | low;
}

#ifdef EXAMPLE_WAIT_IRQ
/* The privileged specification's order for RV32: never below both the old and the new
 * value in between. */
static void mtimecmp_set(uint64_t at) {
  *clint(CLINT_MTIMECMP) = 0xFFFFFFFFu;
  *clint(CLINT_MTIMECMP + 4u) = (uint32_t)(at >> 32);
  *clint(CLINT_MTIMECMP) = (uint32_t)at;
}
#endif

static const char* watchdog_waits_for; /* NULL: disarmed */
static uint64_t watchdog_deadline;

static void watchdog_arm(const char* what) {
  watchdog_deadline = mtime_now() + EXAMPLE_WATCHDOG_TICKS;
  watchdog_waits_for = what;
#ifdef EXAMPLE_WAIT_IRQ
  mtimecmp_set(watchdog_deadline);
  example_timer_interrupt_on();
#endif
}

static void watchdog_disarm(void) {
#ifdef EXAMPLE_WAIT_IRQ
  example_timer_interrupt_off();
  mtimecmp_set(~(uint64_t)0);
#endif
  watchdog_waits_for = NULL;
}

/* Names what was waited for, on which wiring, and what came instead; then exits. */
static void watchdog_fire(void) {
  say("FAIL: no ");
  say(watchdog_waits_for);
  say(" within ");
  say_signed(EXAMPLE_WATCHDOG_TICKS);
  say(" mtime ticks (");
  if (dev.wait_mode == SPECULAR_WAIT_POLL) {
    say("polling STATUS of the IP at ");
    say_hex((uint32_t)SPECULAR_BASE);
  } else {
#if defined(EXAMPLE_WAIT_IRQ) && !defined(EXAMPLE_IRQ_DIRECT)
    say("waited on source ");
    say_signed(EXAMPLE_PLIC_SOURCE);
    say(" of the PLIC at ");
    say_hex((uint32_t)EXAMPLE_PLIC_BASE);
    say(", context ");
    say_signed(EXAMPLE_PLIC_CONTEXT);
    if (example_unclaimed_interrupts == 0u) {
      say("; no external interrupt came: done_irq on another source, or the context or the PLIC's strides not "
          "the platform's?");
    } else {
      say("; ");
      say_signed(example_unclaimed_interrupts);
      say(" external interrupts had nothing to claim: done_irq wired straight to the hart? that is the "
          "irq_direct build");
    }
#else
    say("waited on the machine external interrupt, done_irq straight to the hart; ");
    if (example_spurious_interrupts == 0u) {
      say("none came: done_irq wired to a PLIC? that is the irq build");
    } else {
      say_signed(example_spurious_interrupts);
      say(" came with STATUS.DONE clear");
    }
#endif
  }
  say(")\n");
  example_status = EXIT_WATCHDOG;
  example_exit(EXIT_WATCHDOG);
}

static void watchdog_check(void) {
  if (watchdog_waits_for != NULL && mtime_now() >= watchdog_deadline) watchdog_fire();
}

/* The driver's idle hook while it polls. */
static void poll_under_watchdog(void* context) {
  (void)context;
  watchdog_check();
}
#else
static void watchdog_arm(const char* what) { (void)what; }
static void watchdog_disarm(void) {}
static void watchdog_check(void) {}
#endif

/* ---- interrupts ----------------------------------------------------------------- */

#if defined(EXAMPLE_WAIT_IRQ) && !defined(EXAMPLE_IRQ_DIRECT)
/* The PLIC's registers: offsets (SiFive's layout; the per-context strides are options,
 * riscv-vp's FE310_PLIC packs its contexts closer). */
#define PLIC_PRIORITY (4u * EXAMPLE_PLIC_SOURCE)
#define PLIC_ENABLE (0x2000u + EXAMPLE_PLIC_ENABLE_STRIDE * EXAMPLE_PLIC_CONTEXT + 4u * (EXAMPLE_PLIC_SOURCE / 32u))
#define PLIC_THRESHOLD (0x200000u + EXAMPLE_PLIC_CONTEXT_STRIDE * EXAMPLE_PLIC_CONTEXT)
#define PLIC_CLAIM (PLIC_THRESHOLD + 4u) /* read: claim; write: complete */

/* Volatile loads and stores, or the platform's accessors (the host test's PLIC model). */
static uint32_t plic_read(uint32_t offset) {
  const uintptr_t address = (uintptr_t)EXAMPLE_PLIC_BASE + offset;
#ifdef EXAMPLE_BUS
  const specular_bus* bus = example_platform_bus();
  if (bus != NULL && bus->read32 != NULL) return bus->read32(bus->context, address);
#endif
  return *(volatile uint32_t*)address;
}
static void plic_write(uint32_t offset, uint32_t value) {
  const uintptr_t address = (uintptr_t)EXAMPLE_PLIC_BASE + offset;
#ifdef EXAMPLE_BUS
  const specular_bus* bus = example_platform_bus();
  if (bus != NULL && bus->write32 != NULL) {
    bus->write32(bus->context, address, value);
    return;
  }
#endif
  *(volatile uint32_t*)address = value;
}

/* Priority, threshold and enable, then every source already pending claimed and
 * completed: done_irq rose at the end of each polled operation, so the PLIC's gateway
 * holds our source pending before any interrupt is wanted. Machine interrupts are still
 * off (mstatus.MIE), so nothing is taken here. */
void example_plic_on(void);
void example_plic_on(void) {
  uint32_t id;
  plic_write(PLIC_PRIORITY, 1u);
  plic_write(PLIC_THRESHOLD, 0u);
  plic_write(PLIC_ENABLE, plic_read(PLIC_ENABLE) | 1u << (EXAMPLE_PLIC_SOURCE % 32u));
  while ((id = plic_read(PLIC_CLAIM)) != 0u) plic_write(PLIC_CLAIM, id);
}
#endif

#ifdef EXAMPLE_WAIT_IRQ
/* The driver's idle hook: sleep until the interrupt (the flag is tested with interrupts
 * masked, in example_sleep_unless). */
static void sleep_until_interrupt(void* context) {
  (void)context; /* the platform's, if it gave accessors */
  watchdog_check();
  example_sleep_unless(&dev.irq_pending);
}
#endif

/* A done interrupt counts only while STATUS.DONE is set. One with DONE clear is spurious:
 * an edge a decoupled platform delivers late (at the CPU's next sync), from an operation
 * already polled and acknowledged, or a line still high at mret under a long quantum
 * (docs/integration/riscv_vp.md). */
static void done_interrupt(void) {
  if ((specular_read(&dev, SPECULAR_STATUS_OFFSET) & SPECULAR_STATUS_DONE_MASK) == 0u) {
    ++example_spurious_interrupts;
    watchdog_check(); /* one that keeps coming starves the timer's interrupt */
    return;
  }
  ++example_interrupts;
  specular_irq_handler(&dev); /* acknowledges (done_irq falls) and sets dev.irq_pending */
}

static void external_interrupt(void) {
#if defined(EXAMPLE_WAIT_IRQ) && !defined(EXAMPLE_IRQ_DIRECT)
  const uint32_t id = plic_read(PLIC_CLAIM);
  if (id == EXAMPLE_PLIC_SOURCE) {
    done_interrupt();
  } else {
    ++example_unclaimed_interrupts; /* nothing (0) or another source: not done_irq's */
    watchdog_check();
  }
  if (id != 0u) plic_write(PLIC_CLAIM, id); /* complete: the gateway takes the source again */
#else
  done_interrupt(); /* the level falls with the acknowledging store */
#endif
}

/* What sits at a faulting address the example itself uses, for the unexpected-trap line. */
static const char* fault_hint(uintptr_t address) {
#if defined(EXAMPLE_WAIT_IRQ) && !defined(EXAMPLE_IRQ_DIRECT)
  if (address - (uintptr_t)EXAMPLE_PLIC_BASE < 0x4000000u)
    return " (no PLIC at EXAMPLE_PLIC_BASE? with done_irq straight to the hart, that is the irq_direct build)";
#endif
#if EXAMPLE_WATCHDOG_TICKS != 0
  if (address - (uintptr_t)EXAMPLE_CLINT_BASE < 0x10000u)
    return " (no CLINT at EXAMPLE_CLINT_BASE for the watchdog? set it, or EXAMPLE_WATCHDOG_TICKS=0 for none)";
#endif
  (void)address;
  return "";
}

/* The length of the instruction at `address`: 2 for a compressed one (low bits not 11). */
static uintptr_t instruction_length(uintptr_t address) {
  return (*(const volatile uint16_t*)address & 3u) == 3u ? 4u : 2u;
}

/* Called by startup.S's trap entry for every trap; returns where to resume (mepc). */
uintptr_t example_trap(uintptr_t mcause, uintptr_t mepc, uintptr_t mtval);
uintptr_t example_trap(uintptr_t mcause, uintptr_t mepc, uintptr_t mtval) {
  switch (mcause) {
    case MCAUSE_MACHINE_EXTERNAL:
      external_interrupt();
      return mepc;
#if EXAMPLE_WATCHDOG_TICKS != 0
    case MCAUSE_MACHINE_TIMER: /* only the watchdog enables it */
      if (watchdog_waits_for == NULL) break;
      watchdog_fire();
      return mepc;
#endif
    case MCAUSE_LOAD_ACCESS_FAULT:
    case MCAUSE_STORE_ACCESS_FAULT:
    case MCAUSE_LOAD_PAGE_FAULT:
    case MCAUSE_STORE_PAGE_FAULT:
      /* An access the IP refused, as an initiator that turns an error response into an
       * exception reports it. Skip the instruction (a skipped load leaves its register as
       * it was); specular_check_error then gives the cause. A fault elsewhere is a bug. */
      if (mtval - (uintptr_t)SPECULAR_BASE >= SPECULAR_MAP_SIZE) break;
      ++example_bus_faults;
      example_last_fault_cause = (uint32_t)mcause;
      example_last_fault_address = (uint32_t)mtval;
      return mepc + instruction_length(mepc);
    case MCAUSE_ECALL_FROM_M:
      return mepc + instruction_length(mepc); /* a console or exit call the platform does not take */
    default:
      break;
  }
  say("FAIL: unexpected trap, mcause ");
  say_hex((uint32_t)mcause);
  say(" at ");
  say_hex((uint32_t)mepc);
  say(", mtval ");
  say_hex((uint32_t)mtval);
  say(fault_hint(mtval));
  say("\n");
  example_status = EXIT_UNEXPECTED_TRAP;
  example_exit(EXIT_UNEXPECTED_TRAP);
  return mepc;
}

/* ---- the program ---------------------------------------------------------------- */

static int run(void) {
  static const uint32_t row_cos[EXAMPLE_PIXELS] = EXAMPLE_ROW_COS;
  static const uint32_t row_rgb[3] = EXAMPLE_ROW_RGB;
  static const int32_t expected_row[3u * EXAMPLE_PIXELS] = EXAMPLE_EXPECTED_ROW_OUT;
  static const int32_t expected_one[3] = EXAMPLE_EXPECTED_ONE_OUT;
  static const char* const channel[3] = {"R (pin 24)", "G (pin 25)", "B (pin 26)"};
  static int32_t out[3u * EXAMPLE_PIXELS];
  const specular_operands one = {EXAMPLE_ONE_COS, EXAMPLE_ONE_N, EXAMPLE_ONE_RGB};
  specular_result result;
  size_t i;
  int ch;
  int status;

#ifdef EXAMPLE_BUS
  status = specular_init(&dev, (uintptr_t)SPECULAR_BASE, example_platform_bus()); /* the platform's accessors */
#else
  status = specular_init(&dev, (uintptr_t)SPECULAR_BASE, NULL); /* volatile accesses, polling */
#endif
  if (status != SPECULAR_OK) return driver_failed("specular_init", status);
#if EXAMPLE_WATCHDOG_TICKS != 0
  if (dev.bus.idle == NULL) dev.bus.idle = poll_under_watchdog;
#endif

  /* A refused access: N = 1001 written raw (the driver's own calls check it first). */
  specular_write(&dev, SPECULAR_N_OFFSET, SPECULAR_N_MAX + 1u);
  status = specular_check_error(&dev);
  say("refusal: N = 1001 ");
  if (example_bus_faults != 0u) {
    say("trapped (mcause ");
    say_signed(example_last_fault_cause);
    say(", mtval ");
    say_hex(example_last_fault_address);
    say(") and skipped; ");
  } else {
    say("completed without a trap; ");
  }
  if (status != SPECULAR_ERR_REFUSED || dev.cause != SPECULAR_STATUS_CAUSE_N_OUT_OF_RANGE) {
    say("FAIL: specular_check_error did not report cause N_OUT_OF_RANGE\n");
    return EXIT_REFUSAL_NOT_REPORTED;
  }
  say("specular_check_error: cause ");
  say_signed(dev.cause);
  say(" (N out of range), ERROR_ADDRESS ");
  say_hex(dev.error_address);
  say("\n");

  watchdog_arm("STATUS.DONE");
  status = specular_compute(&dev, &one, &result);
  watchdog_disarm();
  if (status != SPECULAR_OK) return driver_failed("specular_compute", status);
  example_reg9[0] = result.reg9_pass1;
  example_reg9[1] = result.reg9_pass2;
  for (ch = 0; ch < 3; ++ch)
    if (!same("one operation", -1, channel[ch], result.out[ch], expected_one[ch])) return EXIT_RESULT_DIFFERS;
  if (!same("one operation", -1, "register 9 after pass 1", result.reg9_pass1, EXAMPLE_EXPECTED_ONE_REG9_PASS1) ||
      !same("one operation", -1, "register 9 after pass 2", result.reg9_pass2, EXAMPLE_EXPECTED_ONE_REG9_PASS2))
    return EXIT_RESULT_DIFFERS;
  say("one operation (polled): pins 24-26 and register 9 equal to Core\n");

#ifdef EXAMPLE_WAIT_IRQ
  dev.bus.idle = sleep_until_interrupt; /* the accessors stay: volatile, or the platform's */
#ifndef EXAMPLE_IRQ_DIRECT
  example_plic_on();
#endif
  dev.wait_mode = SPECULAR_WAIT_IRQ;
  dev.poll_limit = 0u; /* wfi wakes on the interrupt (or the watchdog's timer): no need to count */
  watchdog_arm("done_irq interrupt");
  example_interrupts_on();
#else
  watchdog_arm("STATUS.DONE");
#endif
#ifdef EXAMPLE_ENERGY_COUNTER
  const uint64_t energy_before = energy_counter_read(ENERGY_COUNTER_PJ);
  const uint64_t operations_before = energy_counter_read(ENERGY_COUNTER_OPERATIONS);
#endif
  status = specular_shade(&dev, EXAMPLE_ROW_N, row_rgb, row_cos, EXAMPLE_PIXELS, out);
  watchdog_disarm();
#ifdef EXAMPLE_ENERGY_COUNTER
  {
    const uint64_t row_pj = energy_counter_read(ENERGY_COUNTER_PJ) - energy_before;
    const uint64_t row_operations = energy_counter_read(ENERGY_COUNTER_OPERATIONS) - operations_before;
    say("energy of the row (the platform's counter at ");
    say_hex((uint32_t)EXAMPLE_ENERGY_COUNTER);
    say("): ");
    say_signed((int64_t)(row_pj / EXAMPLE_PIXELS));
    say(" pJ per pixel, ");
    say_signed((int64_t)(row_pj / 1000u));
    say(" nJ for the row of ");
    say_signed(EXAMPLE_PIXELS);
    say(" pixels, ");
    say_signed((int64_t)row_operations);
    say(" operations\n");
  }
#endif
  if (status != SPECULAR_OK) return driver_failed("specular_shade", status);
  for (i = 0; i < 3u * EXAMPLE_PIXELS; ++i) {
    example_results[i] = out[i];
    if (!same("pixel", (int64_t)(i / 3u), channel[i % 3u], out[i], expected_row[i])) return EXIT_RESULT_DIFFERS;
  }
#ifdef EXAMPLE_WAIT_IRQ
  say("row of ");
  say_signed(EXAMPLE_PIXELS);
  say(" pixels (by interrupt, ");
  say_signed(example_interrupts);
  say(" taken): pins 24-26 equal to Core\n");
#else
  say("row of ");
  say_signed(EXAMPLE_PIXELS);
  say(" pixels (polled): pins 24-26 equal to Core\n");
#endif
  return 0;
}

int main(void);
int main(void) {
  say("specular example: IP at ");
  say_hex((uint32_t)SPECULAR_BASE);
#if defined(EXAMPLE_WAIT_IRQ) && defined(EXAMPLE_IRQ_DIRECT)
  say(", interrupt straight to the hart\n");
#elif defined(EXAMPLE_WAIT_IRQ)
  say(", interrupt through the PLIC at ");
  say_hex((uint32_t)EXAMPLE_PLIC_BASE);
  say(" source ");
  say_signed(EXAMPLE_PLIC_SOURCE);
  say("\n");
#else
  say(", polled\n");
#endif
  example_status = run();
  say(example_status == 0 ? "PASS: every result equal to Core\n" : "FAIL\n");
  return example_status;
}
