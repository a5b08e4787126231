/// \file
/// ROM 38 of the RTL holds one image per device that can be built: one bank per
/// (constants, normalisation) pair, chosen by its configuration input cfg_rom38_bank.
/// Written once, in the library below both of its users: the image generator
/// (rtl/romgen) and the twin's wrappers (twin/).
#pragma once

#include "specular/core.h"

namespace specular {

/// Bank address bits: 3 constants policies × 4 normalisations in 16 banks.
constexpr int rom38_bank_bits = 4;

/// bank = 4 · constants + normalisation (the enums' values; saturation is adder 8's
/// concern, not ROM 38's).
constexpr unsigned rom38_bank(Constants constants, Normalisation normalisation) {
  return 4u * static_cast<unsigned>(constants) + static_cast<unsigned>(normalisation);
}
/// The bank of a device built with `config`.
constexpr unsigned rom38_bank(const Config& config) {
  return rom38_bank(config.constants, config.normalisation);
}

/// Every Constants policy, in the order of its values.
constexpr Constants every_constants[] = {Constants::patent, Constants::minimax_half,
                                         Constants::minimax};
/// Every Normalisation policy, in the order of its values.
constexpr Normalisation every_normalisation[] = {Normalisation::patent, Normalisation::energy,
                                                 Normalisation::none, Normalisation::device_energy};

}  // namespace specular
