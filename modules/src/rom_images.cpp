#include "specular/rom_images.h"

#include <stdexcept>

namespace specular {

std::vector<std::optional<arith::Rom38Table>> rom38_bank_tables(const Formats& formats, int bank_bits) {
  std::vector<std::optional<arith::Rom38Table>> banks(std::size_t{1} << bank_bits);
  for (const Constants constants : every_constants)
    for (const Normalisation normalisation : every_normalisation) {
      Config config;
      config.widths = formats.widths;
      config.normalisation = normalisation;
      config.constants = constants;
      try {
        banks.at(rom38_bank(config)).emplace(formats, config);
      } catch (const std::invalid_argument&) {
        // refused by the device too (Rom38Table's message names why)
      }
    }
  return banks;
}

RomImages rom_images(const Formats& formats, int bank_bits) {
  RomImages images;
  const arith::Rom5Table rom5(formats);
  images.rom5.assign(rom5.words().begin(), rom5.words().end());

  const std::size_t bank_words = static_cast<std::size_t>(formats.rom38_words());
  images.rom38.assign(bank_words << bank_bits, 0);
  const auto tables = rom38_bank_tables(formats, bank_bits);
  for (std::size_t b = 0; b < tables.size(); ++b) {
    if (!tables[b]) continue;
    ++images.rom38_banks_filled;
    for (std::size_t n = 0; n < bank_words; ++n)
      images.rom38[b * bank_words + n] = static_cast<std::uint64_t>(tables[b]->words()[n]);
  }
  return images;
}

}  // namespace specular
