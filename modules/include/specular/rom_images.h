/// \file
/// The words of ROM 5 and ROM 38 as the RTL holds them, built once from the library's
/// tables for both of their users: specular_romgen writes them as $readmemh images (for
/// Icarus, Yosys and the silicon flow), and the twin (twin/) writes them straight into its
/// verilated ROMs, so the installed twin reads no file (docs/integration/package.md).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "specular/arith.h"
#include "specular/rom38_banks.h"

namespace specular {

/// ROM 38's tables, one per bank at rom38_bank() for 2^bank_bits banks. A (constants,
/// normalisation) pair whose table the device refuses (a word ROM 38 cannot hold) has
/// none: its bank holds zeros, as unused banks do.
std::vector<std::optional<arith::Rom38Table>> rom38_bank_tables(const Formats& formats,
                                                                int bank_bits = rom38_bank_bits);

/// Both ROMs in address order, each word's bits right-aligned (ROM 38 words unsigned).
struct RomImages {
  std::vector<std::uint64_t> rom5;   ///< 2^rom5_addr_bits words of rom5_word_bits
  std::vector<std::uint64_t> rom38;  ///< bank-major: word b · rom38_words() + n
  int rom38_banks_filled = 0;        ///< banks that hold a table
};
/// ROM 5's table and every bank of ROM 38 for `formats`, as RomImages.
RomImages rom_images(const Formats& formats, int bank_bits = rom38_bank_bits);

}  // namespace specular
