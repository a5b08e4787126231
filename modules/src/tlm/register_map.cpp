#include "specular/tlm/register_map.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace specular {

const char* to_string(Access access) {
  switch (access) {
    case Access::read_only: return "RO";
    case Access::read_write: return "RW";
    case Access::write_1_to_clear: return "R/W1C";
    case Access::self_clearing: return "W (reads 0)";
  }
  return "?";
}

const char* to_string(ErrorCause cause) {
  switch (cause) {
    case ErrorCause::none: return "none";
    case ErrorCause::cos_out_of_range: return "cos_out_of_range";
    case ErrorCause::n_out_of_range: return "n_out_of_range";
    case ErrorCause::rgb_out_of_range: return "rgb_out_of_range";
    case ErrorCause::read_only: return "read_only";
    case ErrorCause::reserved_bits: return "reserved_bits";
    case ErrorCause::busy: return "busy";
    case ErrorCause::address: return "address";
    case ErrorCause::burst: return "burst";
    case ErrorCause::byte_enable: return "byte_enable";
    case ErrorCause::command: return "command";
  }
  return "unknown";
}

const char* describe(ErrorCause cause) {
  switch (cause) {
    case ErrorCause::none: return "no error since the last clear";
    case ErrorCause::cos_out_of_range: return "COS or a BATCH_COS word above 1.0 (65536 for U1.16)";
    case ErrorCause::n_out_of_range: return "N outside 1..1000";
    case ErrorCause::rgb_out_of_range: return "R, G or B above 255 (the RGB format's maximum)";
    case ErrorCause::read_only: return "write to a read-only register or window";
    case ErrorCause::reserved_bits: return "CONTROL written with a bit other than START set";
    case ErrorCause::busy: return "START or an operand write while an operation is in flight";
    case ErrorCause::address: return "unmapped or misaligned address (not naturally aligned), or a burst running past its window";
    case ErrorCause::burst: return "a length the row does not take (registers: 1, 2, 4, or 8 at a doubleword offset; windows: whole words), a sub-word write to a window, or streaming";
    case ErrorCause::byte_enable: return "byte enables that disable any byte";
    case ErrorCause::command: return "a command other than read, write or ignore";
  }
  return "unknown cause";
}

std::uint32_t config_word(const Config& config) {
  return config_word(config.normalisation, config.saturation, config.widths.cos_frac_bits,
                     config.widths.out_frac_bits, config.widths.rgb_bits, config.constants);
}

namespace {
// Registers live below this offset and are decoded through a word table; windows
// lie above it and are few.
constexpr std::uint32_t register_block = 0x100;

constexpr std::array<std::int8_t, register_block / 4> build_word_table() {
  std::array<std::int8_t, register_block / 4> table{};
  for (auto& entry : table) entry = -1;
  for (std::size_t i = 0; i < register_count; ++i) {
    const RegisterInfo& row = register_map[i];
    if (row.end() > register_block) continue;
    for (std::uint32_t w = 0; w < row.words; ++w)
      table[row.offset / 4 + w] = static_cast<std::int8_t>(i);
  }
  return table;
}
constexpr auto word_table = build_word_table();
}  // namespace

const RegisterInfo* decode(std::uint64_t offset) {
  if (offset % 4 != 0) return nullptr;
  if (offset < register_block) {
    const int index = word_table[offset / 4];
    return index < 0 ? nullptr : &register_map[static_cast<std::size_t>(index)];
  }
  for (const RegisterInfo& row : register_map)
    if (row.end() > register_block && offset >= row.offset && offset < row.end()) return &row;
  return nullptr;
}

namespace {
std::string hex(std::uint32_t value, int digits) {
  std::ostringstream s;
  s << "0x" << std::hex << std::uppercase;
  s.width(digits);
  s.fill('0');
  s << value;
  return s.str();
}

std::string offsets(std::uint32_t first, std::uint32_t last) {
  return first == last ? hex(first, 3) : hex(first, 3) + "–" + hex(last, 3);
}

/// A register's offset, or a window's first and last byte.
std::string row_offsets(const RegisterInfo& row) {
  return row.words == 1 ? hex(row.offset, 3) : offsets(row.offset, row.end() - 1);
}

/// The reset cell: one value, or the words of an alias window that differ from it.
std::string reset_cell(const RegisterInfo& row) {
  std::string cell = hex(row.reset, 8);
  if (row.reg != Reg::operands && row.reg != Reg::results) return cell;
  for (std::uint32_t w = 0; w < row.words; ++w) {
    const std::uint32_t value = reset_of_word(row, w);
    if (value == row.reset) continue;
    const Reg alias = row.reg == Reg::operands ? operand_register(w) : result_register(w);
    cell += "; word " + std::to_string(w) + " (" + info(alias).name + "): " + hex(value, 8);
  }
  return cell;
}

std::string cause_cell(ErrorCause cause) {
  return std::string("`") + to_string(cause) + "` (" + std::to_string(static_cast<int>(cause)) +
         ")";
}

/// What refuses a write to `row`, with the TLM response.
std::string write_refusals(const RegisterInfo& row) {
  switch (row.access) {
    case Access::read_only:
      return cause_cell(ErrorCause::read_only) + ", `TLM_COMMAND_ERROR_RESPONSE`";
    case Access::write_1_to_clear: return "none: 1s clear their flags, 0s change nothing";
    case Access::read_write:
    case Access::self_clearing: break;
  }
  std::string causes;
  if (row.reg == Reg::operands) {  // word by word, as the registers behind it
    std::vector<ErrorCause> seen;
    for (std::uint32_t w = 0; w < operand_words; ++w) {
      const ErrorCause cause = info(operand_register(w)).value_check;
      if (cause == ErrorCause::none || std::find(seen.begin(), seen.end(), cause) != seen.end())
        continue;
      causes += (seen.empty() ? "each word as its register: " : ", ") + cause_cell(cause);
      seen.push_back(cause);
    }
    causes += "; ";
  } else if (row.value_check != ErrorCause::none) {
    causes = cause_cell(row.value_check) + "; ";
  }
  return causes + cause_cell(ErrorCause::busy) +
         " while an operation is in flight; `TLM_GENERIC_ERROR_RESPONSE`";
}

std::string hole_row(std::uint32_t first, std::uint32_t last) {
  return "| " + offsets(first, last) + " | *hole* | — | — | " + cause_cell(ErrorCause::address) +
         ", `TLM_ADDRESS_ERROR_RESPONSE`, reads too |\n";
}
}  // namespace

std::string register_map_markdown() {
  std::ostringstream s;
  s << "| offset | name | access | reset | description |\n";
  s << "|---|---|---|---|---|\n";
  for (const RegisterInfo& row : register_map)
    s << "| " << row_offsets(row) << " | " << row.name << " | "
      << to_string(row.access) << " | " << reset_cell(row) << " | " << row.description << " |\n";
  return s.str();
}

std::string address_map_markdown() {
  std::ostringstream s;
  s << "| offset | register | access | reset | a write is refused with |\n";
  s << "|---|---|---|---|---|\n";
  std::uint32_t next = 0;  // the first byte not yet listed
  for (const RegisterInfo& row : register_map) {
    if (row.offset > next) s << hole_row(next, row.offset - 1);
    s << "| " << row_offsets(row) << " | " << row.name << " | "
      << to_string(row.access) << " | " << reset_cell(row) << " | " << write_refusals(row)
      << " |\n";
    next = row.end();
  }
  if (next < map_size) s << hole_row(next, map_size - 1);
  s << "| ≥ " << hex(map_size, 3) << " | outside the map | — | — | "
    << cause_cell(ErrorCause::address) << ", `TLM_ADDRESS_ERROR_RESPONSE`, reads too |\n";
  return s.str();
}

std::string error_cause_markdown() {
  std::ostringstream s;
  s << "| cause | name | meaning |\n";
  s << "|---|---|---|\n";
  for (std::uint8_t code = 0; code < error_cause_count; ++code) {
    const auto cause = static_cast<ErrorCause>(code);
    s << "| " << static_cast<int>(code) << " | " << to_string(cause) << " | " << describe(cause)
      << " |\n";
  }
  return s.str();
}

}  // namespace specular
