// The C driver reads BATCH_CAPACITY at init (issue 46): specular_shade() chunks by the
// capacity the IP reports, and with 0 (a view without batch windows, as the Verilog IP
// specular_ip_axi is, docs/rtl_ip.md) computes the pixels one operation each through COS
// and START. Against a register-level IP written here in C++ without SystemC: it keeps
// the registers the driver uses, runs Core when started, and counts every window access;
// it refuses a window word at or above its capacity as the TLM target refuses a hole.
// Expected results are Core's, computed here separately for each pixel.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "specular/core.h"
#include "specular/specular_driver.h"
#include "specular/tlm/register_map.h"

namespace specular {
namespace {

constexpr std::uintptr_t ip_base = 0x50000000u;

struct ComputingIp {
  explicit ComputingIp(std::uint32_t capacity) : capacity(capacity) {
    regs[offset_of(Reg::id)] = device_id;
    regs[offset_of(Reg::version)] = map_version;
    regs[offset_of(Reg::config)] = config_word(Config{});
    regs[offset_of(Reg::batch_capacity)] = capacity;
  }
  std::uint32_t capacity;
  Core core;
  std::map<std::uint32_t, std::uint32_t> regs;
  std::vector<std::uint32_t> batch_out;   ///< 3 words per operation, by BATCH_COS word
  std::size_t starts = 0;                 ///< CONTROL.START writes
  std::size_t window_writes = 0;          ///< BATCH_COS words written
  std::size_t window_reads = 0;           ///< BATCH_OUT words read
  std::uint32_t highest_batch_word = 0;   ///< the highest BATCH_COS word index written
  std::size_t refused = 0;                ///< window accesses beyond the capacity

  void refuse(std::uint32_t offset) {
    ++refused;
    regs[offset_of(Reg::status)] |= status_bits::error;
    regs[offset_of(Reg::error_address)] = offset;
  }
  void run_into(std::uint32_t cos, std::uint32_t* out) {
    const Result r = core.run({cos, regs[offset_of(Reg::n)],
                               {regs[offset_of(Reg::r)], regs[offset_of(Reg::g)], regs[offset_of(Reg::b)]}});
    for (int ch = 0; ch < 3; ++ch) out[ch] = static_cast<std::uint32_t>(r.out[ch]);
    regs[offset_of(Reg::status)] |= status_bits::done;
  }
  std::uint32_t read(std::uint32_t offset) {
    const std::uint32_t out_base = offset_of(Reg::batch_out);
    if (offset >= out_base && offset < out_base + 4 * 3 * batch_capacity) {
      const std::uint32_t word = (offset - out_base) / 4;
      if (word >= 3 * capacity) {
        refuse(offset);
        return 0u;
      }
      ++window_reads;
      return word < batch_out.size() ? batch_out[word] : 0u;
    }
    return regs[offset];
  }
  void write(std::uint32_t offset, std::uint32_t value) {
    const std::uint32_t cos_base = offset_of(Reg::batch_cos);
    if (offset >= cos_base && offset < cos_base + 4 * batch_capacity) {
      const std::uint32_t word = (offset - cos_base) / 4;
      if (word >= capacity) return refuse(offset);
      ++window_writes;
      highest_batch_word = std::max(highest_batch_word, word);
      if (batch_out.size() < 3 * (word + 1)) batch_out.resize(3 * (word + 1));
      return run_into(value, &batch_out[3 * word]);
    }
    if (offset == offset_of(Reg::status)) {
      regs[offset] &= ~(value & (status_bits::done | status_bits::error));  // W1C
      return;
    }
    if (offset == offset_of(Reg::control)) {
      if (value & 1u) {
        ++starts;
        std::uint32_t out[3];
        run_into(regs[offset_of(Reg::cos)], out);
        for (int ch = 0; ch < 3; ++ch) regs[offset_of(Reg::out_r) + 4 * ch] = out[ch];
      }
      return;
    }
    regs[offset] = value;
  }
  static std::uint32_t read32(void* context, std::uintptr_t address) {
    return static_cast<ComputingIp*>(context)->read(static_cast<std::uint32_t>(address - ip_base));
  }
  static void write32(void* context, std::uintptr_t address, std::uint32_t value) {
    static_cast<ComputingIp*>(context)->write(static_cast<std::uint32_t>(address - ip_base), value);
  }
  specular_bus bus() {
    specular_bus b{};
    b.read32 = read32;
    b.write32 = write32;
    b.context = this;
    return b;
  }
};

/// `count` random cos codes shaded with n = 37 and R, G, B = 255, 128, 3 through the
/// driver against `ip`; every pixel must be Core's.
void expect_shade_equals_core(ComputingIp& ip, std::size_t count) {
  const specular_bus bus = ip.bus();
  specular_dev dev;
  ASSERT_EQ(specular_init(&dev, ip_base, &bus), SPECULAR_OK);
  EXPECT_EQ(dev.batch_capacity, ip.capacity);
  std::mt19937 random(20261204u + static_cast<unsigned>(ip.capacity));
  std::vector<std::uint32_t> cos(count);
  for (auto& c : cos) c = random() % 65537u;
  const std::uint32_t rgb[3] = {255u, 128u, 3u};
  std::vector<std::int32_t> out(3 * count, 0x7EADBEEF);
  ASSERT_EQ(specular_shade(&dev, 37u, rgb, cos.data(), count, out.data()), SPECULAR_OK);
  const Core core;
  for (std::size_t i = 0; i < count; ++i) {
    const Result expected = core.run({cos[i], 37u, {255u, 128u, 3u}});
    for (int ch = 0; ch < 3; ++ch)
      ASSERT_EQ(out[3 * i + ch], expected.out[ch]) << "pixel " << i << " channel " << ch;
  }
  EXPECT_EQ(ip.refused, 0u) << "the driver touched a window word beyond BATCH_CAPACITY";
}

TEST(FirmwareDriverCapacity, NoWindowsOneOperationPerPixel) {
  ComputingIp ip(0);
  expect_shade_equals_core(ip, 37);
  EXPECT_EQ(ip.starts, 37u);
  EXPECT_EQ(ip.window_writes + ip.window_reads, 0u);
}

TEST(FirmwareDriverCapacity, ChunksOfTheCapacityRead) {
  ComputingIp ip(5);
  expect_shade_equals_core(ip, 12);  // chunks of 5, 5 and 2
  EXPECT_EQ(ip.starts, 0u);
  EXPECT_EQ(ip.window_writes, 12u);
  EXPECT_EQ(ip.highest_batch_word, 4u);
  EXPECT_EQ(ip.window_reads, 3u * 12u);
}

TEST(FirmwareDriverCapacity, MoreThanTheMapHoldsIsAnotherMap) {
  ComputingIp ip(batch_capacity + 1);
  const specular_bus bus = ip.bus();
  specular_dev dev;
  EXPECT_EQ(specular_init(&dev, ip_base, &bus), SPECULAR_ERR_VERSION);
}

}  // namespace
}  // namespace specular
