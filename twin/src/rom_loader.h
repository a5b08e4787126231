// ROM 5 and ROM 38 of a verilated device hold the library's words (specular::rom_images),
// written here when a model is made: the twin reads no image file, so the installed
// library works wherever it is copied (twin/rom_words.vlt keeps the memories writable;
// docs/integration/package.md). Include after the verilated model's root header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <list>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <verilated.h>

#include "specular/rom_images.h"
#include "same_formats.h"

namespace specular {

/// Copies `words` into a verilated memory; a memory of another depth means the model was
/// verilated at other widths than `formats`, a bug of the caller.
template <class Word, std::size_t Depth>
void write_rom_words(VlUnpacked<Word, Depth>& memory, const std::vector<std::uint64_t>& words,
                     const char* rom) {
  if (words.size() != Depth)
    throw std::logic_error(std::string("RTL twin: ") + rom + " of the verilated model has " +
                           std::to_string(Depth) + " words, the library's table " +
                           std::to_string(words.size()) + ": model and formats differ in width");
  for (std::size_t address = 0; address < Depth; ++address)
    memory[address] = static_cast<Word>(words[address]);
}

/// rom_images() costs about 50 ms (twelve ROM 38 tables) and a process makes many models
/// at one or two width sets (tests, fuzzing, a platform per target): made once per set.
inline const RomImages& rom_images_once(const Formats& formats) {
  static std::mutex mutex;
  static std::list<std::pair<Widths, RomImages>> made;  // a list: references stay valid
  const std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [widths, images] : made)
    if (same_formats(widths, formats.widths)) return images;
  made.emplace_back(formats.widths, rom_images(formats));
  return made.back().second;
}

/// Whether `Root` (a verilated model's rootp class) is specular_device (the drawn
/// twin) rather than specular_device_sync: their memories carry the top module's name.
template <class Root, class = void>
struct IsDrawnDeviceRoot : std::false_type {};
template <class Root>
struct IsDrawnDeviceRoot<Root, std::void_t<decltype(&Root::specular_device__DOT__rom5__DOT__mantissa_rom)>>
    : std::true_type {};

/// Writes both ROMs of a verilated specular_device or specular_device_sync (`root`:
/// *top.rootp) with the words of `formats`. Call before the model's first eval().
template <class Root>
void load_rom_words(Root& root, const Formats& formats) {
  const RomImages& images = rom_images_once(formats);
  if constexpr (IsDrawnDeviceRoot<Root>::value) {
    write_rom_words(root.specular_device__DOT__rom5__DOT__mantissa_rom, images.rom5, "ROM 5");
    write_rom_words(root.specular_device__DOT__rom38__DOT__k_rom, images.rom38, "ROM 38");
  } else {
    write_rom_words(root.specular_device_sync__DOT__rom5__DOT__mantissa_rom, images.rom5, "ROM 5");
    write_rom_words(root.specular_device_sync__DOT__rom38__DOT__k_rom, images.rom38, "ROM 38");
  }
}

}  // namespace specular
