/* specular_driver.c: the C driver of specular_driver.h. Freestanding C99: no libc call,
 * no allocation, no floating point; every register offset and bit from specular_regs.h
 * (generated from the C++ register map). */
#include "specular/specular_driver.h"

#define SPECULAR_DEFAULT_POLL_LIMIT 1000000u

/* ---- bus access: the user's accessors, or volatile loads and stores ---------------- */

static uint32_t reg_read(specular_dev* dev, uint32_t offset) {
  const uintptr_t address = dev->base + offset;
  if (dev->bus.read32 != NULL) return dev->bus.read32(dev->bus.context, address);
  return *(volatile const uint32_t*)address;
}

static void reg_write(specular_dev* dev, uint32_t offset, uint32_t value) {
  const uintptr_t address = dev->base + offset;
  if (dev->bus.write32 != NULL) {
    dev->bus.write32(dev->bus.context, address, value);
    return;
  }
  *(volatile uint32_t*)address = value;
}

static void idle(specular_dev* dev) {
  if (dev->bus.idle != NULL) dev->bus.idle(dev->bus.context);
}

uint32_t specular_read(specular_dev* dev, uint32_t offset) { return reg_read(dev, offset); }
void specular_write(specular_dev* dev, uint32_t offset, uint32_t value) { reg_write(dev, offset, value); }

/* ---- set-up and status ------------------------------------------------------------ */

int specular_init(specular_dev* dev, uintptr_t base, const specular_bus* bus) {
  uint32_t config;
  uint32_t cos_frac;
  uint32_t rgb_bits;
  if (dev == NULL) return SPECULAR_ERR_NULL;
  dev->base = base;
  dev->bus.read32 = NULL;
  dev->bus.write32 = NULL;
  dev->bus.read_block = NULL;
  dev->bus.write_block = NULL;
  dev->bus.idle = NULL;
  dev->bus.context = NULL;
  if (bus != NULL) dev->bus = *bus;
  dev->wait_mode = SPECULAR_WAIT_POLL;
  dev->poll_limit = SPECULAR_DEFAULT_POLL_LIMIT;
  dev->irq_pending = 0u;
  dev->cause = SPECULAR_STATUS_CAUSE_NONE;
  dev->error_address = 0u;
  dev->bad_index = 0u;
  dev->cos_max = 0u;
  dev->rgb_max = 0u;
  dev->batch_capacity = 0u;

  if (reg_read(dev, SPECULAR_ID_OFFSET) != SPECULAR_DEVICE_ID) return SPECULAR_ERR_NOT_SPECULAR;
  if ((reg_read(dev, SPECULAR_VERSION_OFFSET) >> 16) != SPECULAR_MAP_VERSION_MAJOR)
    return SPECULAR_ERR_VERSION;
  /* The ranges the IP checks, as it was built (CONFIG is fixed at construction). */
  config = reg_read(dev, SPECULAR_CONFIG_OFFSET);
  cos_frac = SPECULAR_FIELD_GET(SPECULAR_CONFIG_COS_FRAC_BITS, config);
  rgb_bits = SPECULAR_FIELD_GET(SPECULAR_CONFIG_RGB_BITS, config);
  if (cos_frac > 30u || rgb_bits < 1u || rgb_bits > 31u) return SPECULAR_ERR_VERSION;
  dev->cos_max = (uint32_t)1u << cos_frac;
  dev->rgb_max = ((uint32_t)1u << rgb_bits) - 1u;
  /* The batch windows as this view of the IP has them: 0 where they are left out (the
   * Verilog IP, docs/rtl_ip.md); more than the map's windows hold is another map. */
  dev->batch_capacity = reg_read(dev, SPECULAR_BATCH_CAPACITY_OFFSET);
  if (dev->batch_capacity > SPECULAR_BATCH_CAPACITY) return SPECULAR_ERR_VERSION;
  /* A clean start: no result pending, no refusal left over. */
  reg_write(dev, SPECULAR_STATUS_OFFSET, SPECULAR_STATUS_DONE_MASK | SPECULAR_STATUS_ERROR_MASK);
  return SPECULAR_OK;
}

int specular_check_error(specular_dev* dev) {
  uint32_t status;
  if (dev == NULL) return SPECULAR_ERR_NULL;
  status = reg_read(dev, SPECULAR_STATUS_OFFSET);
  if ((status & SPECULAR_STATUS_ERROR_MASK) == 0u) return SPECULAR_OK;
  dev->cause = SPECULAR_FIELD_GET(SPECULAR_STATUS_CAUSE, status);
  dev->error_address = reg_read(dev, SPECULAR_ERROR_ADDRESS_OFFSET);
  reg_write(dev, SPECULAR_STATUS_OFFSET, SPECULAR_STATUS_ERROR_MASK);
  return SPECULAR_ERR_REFUSED;
}

/* ---- one operation ---------------------------------------------------------------- */

static int check_shared(const specular_dev* dev, uint32_t n, const uint32_t rgb[3]) {
  int ch;
  if (n < SPECULAR_N_MIN || n > SPECULAR_N_MAX) return SPECULAR_ERR_N;
  for (ch = 0; ch < 3; ++ch)
    if (rgb[ch] > dev->rgb_max) return SPECULAR_ERR_RGB;
  return SPECULAR_OK;
}

int specular_set_shared(specular_dev* dev, uint32_t n, const uint32_t rgb[3]) {
  int status;
  if (dev == NULL || rgb == NULL) return SPECULAR_ERR_NULL;
  status = check_shared(dev, n, rgb);
  if (status != SPECULAR_OK) return status;
  reg_write(dev, SPECULAR_N_OFFSET, n);
  reg_write(dev, SPECULAR_R_OFFSET, rgb[0]);
  reg_write(dev, SPECULAR_G_OFFSET, rgb[1]);
  reg_write(dev, SPECULAR_B_OFFSET, rgb[2]);
  return SPECULAR_OK;
}

int specular_start(specular_dev* dev, uint32_t cos) {
  if (dev == NULL) return SPECULAR_ERR_NULL;
  if (cos > dev->cos_max) return SPECULAR_ERR_COS;
  dev->irq_pending = 0u;
  reg_write(dev, SPECULAR_COS_OFFSET, cos);
  reg_write(dev, SPECULAR_CONTROL_OFFSET, SPECULAR_CONTROL_START_MASK);
  return SPECULAR_OK;
}

int specular_wait(specular_dev* dev) {
  uint32_t waited = 0u;
  if (dev == NULL) return SPECULAR_ERR_NULL;
  if (dev->wait_mode == SPECULAR_WAIT_IRQ) {
    /* One read, no polling: a refused START raises no interrupt. */
    if (specular_check_error(dev) != SPECULAR_OK) return SPECULAR_ERR_REFUSED;
    while (dev->irq_pending == 0u) {
      if (dev->poll_limit != 0u && waited++ >= dev->poll_limit) return SPECULAR_ERR_TIMEOUT;
      idle(dev);
    }
    return SPECULAR_OK;
  }
  for (;;) {
    const uint32_t status = reg_read(dev, SPECULAR_STATUS_OFFSET);
    if ((status & SPECULAR_STATUS_ERROR_MASK) != 0u) return specular_check_error(dev);
    if ((status & SPECULAR_STATUS_DONE_MASK) != 0u) return SPECULAR_OK;
    if (dev->poll_limit != 0u && ++waited >= dev->poll_limit) return SPECULAR_ERR_TIMEOUT;
    idle(dev);
  }
}

/* REG9_PASS*_LO and _HI joined into the signed 64-bit code (HI is sign-extended). */
static int64_t join(uint32_t lo, uint32_t hi) {
  const uint64_t bits = ((uint64_t)hi << 32) | lo;
  /* Two's complement without implementation-defined conversion. */
  if ((hi & 0x80000000u) == 0u) return (int64_t)bits;
  return -(int64_t)(~bits) - 1;
}

static int32_t signed_word(uint32_t word) {
  if ((word & 0x80000000u) == 0u) return (int32_t)word;
  return -(int32_t)(~word) - 1;
}

int specular_read_result(specular_dev* dev, specular_result* result) {
  if (dev == NULL) return SPECULAR_ERR_NULL;
  if (result == NULL) return SPECULAR_OK;
  result->out[0] = signed_word(reg_read(dev, SPECULAR_OUT_R_OFFSET));
  result->out[1] = signed_word(reg_read(dev, SPECULAR_OUT_G_OFFSET));
  result->out[2] = signed_word(reg_read(dev, SPECULAR_OUT_B_OFFSET));
  result->reg9_pass1 = join(reg_read(dev, SPECULAR_REG9_PASS1_LO_OFFSET),
                            reg_read(dev, SPECULAR_REG9_PASS1_HI_OFFSET));
  result->reg9_pass2 = join(reg_read(dev, SPECULAR_REG9_PASS2_LO_OFFSET),
                            reg_read(dev, SPECULAR_REG9_PASS2_HI_OFFSET));
  return SPECULAR_OK;
}

void specular_ack(specular_dev* dev) {
  if (dev == NULL) return;
  reg_write(dev, SPECULAR_IRQ_ACK_OFFSET, SPECULAR_IRQ_ACK_VALUE);
}

int specular_compute(specular_dev* dev, const specular_operands* in, specular_result* result) {
  int status;
  if (dev == NULL || in == NULL) return SPECULAR_ERR_NULL;
  /* Every argument before any write. */
  status = check_shared(dev, in->n, in->rgb);
  if (status != SPECULAR_OK) return status;
  if (in->cos > dev->cos_max) return SPECULAR_ERR_COS;
  (void)specular_set_shared(dev, in->n, in->rgb);
  (void)specular_start(dev, in->cos);
  status = specular_wait(dev);
  if (status != SPECULAR_OK) return status;
  (void)specular_read_result(dev, result);
  specular_ack(dev);
  return SPECULAR_OK;
}

/* ---- many pixels: the batch windows ------------------------------------------------ */

/* One chunk of k <= dev->batch_capacity operations from BATCH_COS word 0. */
static int shade_chunk(specular_dev* dev, const uint32_t* cos, size_t k, int32_t* out) {
  size_t i;
  int status;
  if (dev->bus.write_block != NULL) {  /* one burst: k operations in one transaction */
    dev->irq_pending = 0u;
    dev->bus.write_block(dev->bus.context, dev->base + SPECULAR_BATCH_COS_OFFSET, cos, k);
    status = specular_wait(dev);
    if (status != SPECULAR_OK) return status;
  } else {
    /* Word by word (a CPU without DMA): each store runs one operation and completes when
     * the operation does (its latency is in the store's response), so the stores go back
     * to back and the driver waits once, after the last. That wait reads STATUS (or, by
     * interrupt, checks STATUS.ERROR once), so a store refused on the way, as busy or out
     * of range, is still reported. Decision: docs/decisions.md, "Batches from a CPU". */
    for (i = 0; i < k; ++i) {
      if (i + 1u == k) dev->irq_pending = 0u; /* the last operation's interrupt is the one */
      reg_write(dev, SPECULAR_BATCH_COS_OFFSET + 4u * (uint32_t)i, cos[i]);
    }
    status = specular_wait(dev);
    if (status != SPECULAR_OK) return status;
  }
  if (dev->bus.read_block != NULL) {
    /* The window's words are the pins' 32-bit two's complement codes. */
    dev->bus.read_block(dev->bus.context, dev->base + SPECULAR_BATCH_OUT_OFFSET, (uint32_t*)out,
                        SPECULAR_BATCH_OUT_WORDS_PER_OPERATION * k);
    for (i = 0; i < SPECULAR_BATCH_OUT_WORDS_PER_OPERATION * k; ++i)
      out[i] = signed_word((uint32_t)out[i]);
  } else {
    for (i = 0; i < SPECULAR_BATCH_OUT_WORDS_PER_OPERATION * k; ++i)
      out[i] = signed_word(reg_read(dev, SPECULAR_BATCH_OUT_OFFSET + 4u * (uint32_t)i));
  }
  specular_ack(dev);
  return SPECULAR_OK;
}

/* Without batch windows (BATCH_CAPACITY 0): one operation per pixel through COS and
 * START, as specular_compute() runs it. */
static int shade_one_by_one(specular_dev* dev, const uint32_t* cos, size_t count, int32_t* out) {
  size_t i;
  int status;
  for (i = 0; i < count; ++i) {
    (void)specular_start(dev, cos[i]);
    status = specular_wait(dev);
    if (status != SPECULAR_OK) return status;
    out[3u * i] = signed_word(reg_read(dev, SPECULAR_OUT_R_OFFSET));
    out[3u * i + 1u] = signed_word(reg_read(dev, SPECULAR_OUT_G_OFFSET));
    out[3u * i + 2u] = signed_word(reg_read(dev, SPECULAR_OUT_B_OFFSET));
    specular_ack(dev);
  }
  return SPECULAR_OK;
}

int specular_shade(specular_dev* dev, uint32_t n, const uint32_t rgb[3], const uint32_t* cos,
                   size_t count, int32_t* out) {
  size_t i;
  int status;
  size_t capacity;
  if (dev == NULL || rgb == NULL || cos == NULL || out == NULL) return SPECULAR_ERR_NULL;
  if (count == 0u) return SPECULAR_ERR_COUNT;
  status = check_shared(dev, n, rgb);
  if (status != SPECULAR_OK) return status;
  for (i = 0; i < count; ++i)
    if (cos[i] > dev->cos_max) {
      dev->bad_index = i;
      return SPECULAR_ERR_COS;
    }
  (void)specular_set_shared(dev, n, rgb);
  capacity = dev->batch_capacity;
  if (capacity == 0u) return shade_one_by_one(dev, cos, count, out);
  for (i = 0; i < count; i += capacity) {
    const size_t k = count - i < capacity ? count - i : capacity;
    status = shade_chunk(dev, cos + i, k, out + SPECULAR_BATCH_OUT_WORDS_PER_OPERATION * i);
    if (status != SPECULAR_OK) return status;
  }
  return SPECULAR_OK;
}

/* ---- interrupt hooks --------------------------------------------------------------- */

void specular_irq_notify(specular_dev* dev) {
  if (dev != NULL) dev->irq_pending = 1u;
}

void specular_irq_handler(specular_dev* dev) {
  if (dev == NULL) return;
  specular_ack(dev);
  dev->irq_pending = 1u;
}

const char* specular_strerror(int status) {
  switch (status) {
    case SPECULAR_OK: return "ok";
    case SPECULAR_ERR_NULL: return "a pointer argument is NULL";
    case SPECULAR_ERR_N: return "n out of range (1..1000)";
    case SPECULAR_ERR_COS: return "cos code out of range (0..1.0, 65536 by default)";
    case SPECULAR_ERR_RGB: return "r, g or b out of range (0..255 by default)";
    case SPECULAR_ERR_COUNT: return "count is 0";
    case SPECULAR_ERR_NOT_SPECULAR: return "ID is not the specular IP's (wrong base address?)";
    case SPECULAR_ERR_VERSION: return "register map version or CONFIG not supported";
    case SPECULAR_ERR_REFUSED: return "the IP refused an access (see dev->cause)";
    case SPECULAR_ERR_TIMEOUT: return "STATUS.DONE did not come within poll_limit";
    default: return "unknown status";
  }
}
