/** \file specular_driver.h
 * \brief A small C driver for the specular colour intensity IP (UA 59965 U).
 *
 * Freestanding C99 (only <stddef.h> and <stdint.h>), usable from C++. One operation:
 * operands in, START, wait (polling STATUS.DONE, or an interrupt hook), pins 24-26
 * (OUT_R, OUT_G, OUT_B) and register 9 (REG9_PASS1, REG9_PASS2) out, acknowledge.
 * Many pixels per call: specular_shade() through the BATCH_COS and BATCH_OUT windows, in
 * chunks of the BATCH_CAPACITY the IP reports (one by one where it has no windows). Every argument is checked before anything is
 * written; a bad one returns an error code naming it (never clamped). An access the IP
 * refused (STATUS.ERROR) returns SPECULAR_ERR_REFUSED with its cause.
 *
 * Bus access: a specular_dev holds the IP's base address and, optionally, a specular_bus
 * of accessor functions. With none (specular_init's `bus` NULL) the driver uses volatile
 * 32-bit loads and stores at base + offset, as bare-metal firmware does. A bus replaces
 * them at run time, with a context pointer: a host test routes them to a TLM socket, an
 * OS to its own MMIO helpers, a platform with a DMA engine adds block transfers. Function
 * pointers rather than macros overridden before the include, because one compiled driver
 * then serves several buses in one program (the host test drives four TLM targets with
 * the same object file), the accessors can carry state (the context), and the default
 * path costs one well-predicted NULL test per access.
 *
 * Not thread-safe: one caller per specular_dev at a time (the ISR only sets a flag).
 */
#ifndef SPECULAR_SPECULAR_DRIVER_H
#define SPECULAR_SPECULAR_DRIVER_H

#include <stddef.h>
#include <stdint.h>

#include "specular/specular_regs.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Return codes: 0 success, negative an error. The argument errors name the argument.
 * specular_strerror() gives each a short English name. */
typedef enum specular_status {
  SPECULAR_OK = 0,               /**< success */
  SPECULAR_ERR_NULL = -1,        /**< a pointer argument is NULL */
  SPECULAR_ERR_N = -2,           /**< n outside SPECULAR_N_MIN..SPECULAR_N_MAX */
  SPECULAR_ERR_COS = -3,         /**< a cos code above 1.0 (1 << CONFIG.COS_FRAC_BITS) */
  SPECULAR_ERR_RGB = -4,         /**< r, g or b above (1 << CONFIG.RGB_BITS) - 1 */
  SPECULAR_ERR_COUNT = -5,       /**< specular_shade: count 0 */
  SPECULAR_ERR_NOT_SPECULAR = -6, /**< ID is not SPECULAR_DEVICE_ID: wrong base address? */
  SPECULAR_ERR_VERSION = -7,     /**< VERSION's major is not SPECULAR_MAP_VERSION_MAJOR */
  SPECULAR_ERR_REFUSED = -8,     /**< the IP refused an access: dev->cause says why */
  SPECULAR_ERR_TIMEOUT = -9      /**< STATUS.DONE did not come within dev->poll_limit polls */
} specular_status;

/** Replaceable bus accessors. `address` is the full address (base + offset). read_block
 * and write_block may be NULL: the driver then uses read32/write32 word by word. Each
 * BATCH_COS store runs one operation and completes when it does (the IP's latency is in
 * the store's response), so a chunk's stores go back to back and the driver waits once
 * after the last (a store that met an operation in flight, on a bus that answers writes
 * early, is refused as busy and reported). A block write to BATCH_COS runs `count`
 * operations in one transaction (a burst), as a DMA engine's would. */
typedef struct specular_bus {
  /** Reads the 32-bit word at `address`; NULL (with write32): volatile loads. */
  uint32_t (*read32)(void* context, uintptr_t address);
  /** Writes `value` to the 32-bit word at `address`; NULL (with read32): volatile stores. */
  void (*write32)(void* context, uintptr_t address, uint32_t value);
  /** Reads `count` consecutive words from `address` in one burst; may be NULL. */
  void (*read_block)(void* context, uintptr_t address, uint32_t* words, size_t count);
  /** Writes `count` consecutive words to `address` in one burst; may be NULL. */
  void (*write_block)(void* context, uintptr_t address, const uint32_t* words, size_t count);
  /** Called in every wait loop (poll or interrupt): e.g. `wfi`, an OS yield, or a
   * simulator's sync. May be NULL (busy-wait). */
  void (*idle)(void* context);
  /** Passed unchanged as the first argument of every accessor above. */
  void* context;
} specular_bus;

/** How specular_wait() waits for an operation's end. */
typedef enum specular_wait_mode {
  SPECULAR_WAIT_POLL = 0, /**< read STATUS until DONE (or ERROR) */
  SPECULAR_WAIT_IRQ = 1   /**< until the interrupt hook ran (specular_irq_notify / _handler) */
} specular_wait_mode;

/** One IP instance: its base address, bus accessors, wait mode and last refusal. Fill
 * it with specular_init(); the fields are readable by the caller. */
typedef struct specular_dev {
  uintptr_t base;           /**< the IP's base address (its window: SPECULAR_MAP_SIZE bytes) */
  specular_bus bus;         /**< read32/write32 NULL: volatile accesses */
  specular_wait_mode wait_mode; /**< how specular_wait() waits: SPECULAR_WAIT_POLL after init */
  uint32_t poll_limit;      /**< STATUS reads (or idle calls) before SPECULAR_ERR_TIMEOUT; 0 = no limit */
  uint32_t cos_max;         /**< from CONFIG at init: 1 << COS_FRAC_BITS */
  uint32_t rgb_max;         /**< from CONFIG at init: (1 << RGB_BITS) - 1 */
  uint32_t batch_capacity;  /**< BATCH_CAPACITY at init: operations per batch chunk; 0 = no windows */
  volatile uint32_t irq_pending; /**< set by the interrupt hook, cleared before each start */
  uint32_t cause;           /**< SPECULAR_STATUS_CAUSE_* of the last refusal (SPECULAR_ERR_REFUSED) */
  uint32_t error_address;   /**< ERROR_ADDRESS of the last refusal */
  size_t bad_index;         /**< specular_shade: the index of the bad cos (SPECULAR_ERR_COS) */
} specular_dev;

/** One operation's operands: cos code (U1.16 by default), n, and R, G, B. */
typedef struct specular_operands {
  uint32_t cos;    /**< cos λ code (pin 17): 0..dev->cos_max (65536 = 1.0 in U1.16) */
  uint32_t n;      /**< specular exponent (pin 18): SPECULAR_N_MIN..SPECULAR_N_MAX */
  uint32_t rgb[3]; /**< light intensities R, G, B (pins 21-23): 0..dev->rgb_max (255) */
} specular_operands;

/** One operation's results: pins 24-26 (signed, S18.13 by default) and register 9 after
 * each pass (signed, S14.22: the two 32-bit halves of REG9_PASS*_LO/HI joined). */
typedef struct specular_result {
  int32_t out[3];      /**< OUT_R, OUT_G, OUT_B: pins 24-26, K·A·I in S18.13 by default */
  int64_t reg9_pass1;  /**< register 9 after pass 1: 1 - n·log2 cos λ, S14.22 */
  int64_t reg9_pass2;  /**< register 9 after pass 2: A = 1 - ½·log2(reg9), S14.22 */
} specular_result;

/** Binds `dev` to the IP at `base` (bus NULL: volatile accesses; otherwise copied), reads
 * ID, VERSION, CONFIG (the ranges of COS and R, G, B) and BATCH_CAPACITY (0 where the
 * view has no batch windows), clears STATUS. Polling by default, poll_limit 1000000.
 * Errors: NULL, NOT_SPECULAR, VERSION (also a BATCH_CAPACITY above SPECULAR_BATCH_CAPACITY). */
int specular_init(specular_dev* dev, uintptr_t base, const specular_bus* bus);

/** Raw register access (offsets: SPECULAR_*_OFFSET), for what the calls below do not cover. */
uint32_t specular_read(specular_dev* dev, uint32_t offset);
/** Writes `value` to the register at `offset` (SPECULAR_*_OFFSET): no check, no wait. */
void specular_write(specular_dev* dev, uint32_t offset, uint32_t value);

/** Checks STATUS.ERROR: if set, records cause and ERROR_ADDRESS in `dev`, clears it (W1C)
 * and returns SPECULAR_ERR_REFUSED; else SPECULAR_OK. */
int specular_check_error(specular_dev* dev);

/** Writes N, R, G, B (shared by the operations that follow). Errors: NULL, N, RGB. */
int specular_set_shared(specular_dev* dev, uint32_t n, const uint32_t rgb[3]);
/** Writes COS and CONTROL.START (clears irq_pending first). Errors: NULL, COS, REFUSED. */
int specular_start(specular_dev* dev, uint32_t cos);
/** Waits for the end of the operation (dev->wait_mode). Errors: REFUSED, TIMEOUT. */
int specular_wait(specular_dev* dev);
/** Reads OUT_R, OUT_G, OUT_B and REG9_PASS1/2 (`result` may be NULL for none). */
int specular_read_result(specular_dev* dev, specular_result* result);
/** Acknowledges: writes 1 to STATUS.DONE (the interrupt's level falls). */
void specular_ack(specular_dev* dev);

/** All of the above for one operation. Errors: NULL, N, COS, RGB, REFUSED, TIMEOUT. */
int specular_compute(specular_dev* dev, const specular_operands* in, specular_result* result);

/** `count` pixels sharing n and R, G, B: cos[i] -> out[3i], out[3i+1], out[3i+2] (pins
 * 24-26), through BATCH_COS and BATCH_OUT in chunks of dev->batch_capacity (read at
 * init), each chunk waited for and acknowledged; with capacity 0 (no windows) one
 * operation per pixel through COS and START. Every cos is checked before anything is written
 * (dev->bad_index names the first bad one). Errors: NULL, COUNT, N, RGB, COS, REFUSED,
 * TIMEOUT. */
int specular_shade(specular_dev* dev, uint32_t n, const uint32_t rgb[3], const uint32_t* cos,
                   size_t count, int32_t* out);

/** Interrupt hooks. specular_irq_notify only sets dev->irq_pending: for a callback that
 * must not touch the bus (a simulator's), or an edge-triggered controller. The driver
 * acknowledges after reading the results. specular_irq_handler also acknowledges
 * (writes STATUS.DONE), as an ISR on a level-sensitive line must before it returns. */
void specular_irq_notify(specular_dev* dev);
/** Interrupt hook for an ISR on the level-sensitive done_irq: sets dev->irq_pending and
 * acknowledges (writes 1 to STATUS.DONE) so the level falls before the ISR returns. */
void specular_irq_handler(specular_dev* dev);

/** A short English name of a return code ("n out of range", ...). */
const char* specular_strerror(int status);

#ifdef __cplusplus
}
#endif

#endif /* SPECULAR_SPECULAR_DRIVER_H */
