// The fuzz targets' view of an input: a little-endian stream of bytes that reads as 0
// past its end, so every input decodes to something (shorter inputs to fewer actions).
#pragma once

#include <cstddef>
#include <cstdint>

namespace specular_fuzz {

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return at_ >= size_; }
  std::uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
  // Low part first, in statements of their own: the operands of | are unsequenced.
  std::uint16_t u16() {
    const std::uint16_t low = u8();
    return static_cast<std::uint16_t>(low | (u8() << 8));
  }
  std::uint32_t u24() {
    const std::uint32_t low = u16();
    return low | (static_cast<std::uint32_t>(u8()) << 16);
  }
  std::uint32_t u32() {
    const std::uint32_t low = u16();
    return low | (static_cast<std::uint32_t>(u16()) << 16);
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

}  // namespace specular_fuzz
