#include "firmware_header.h"

#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "specular/format.h"
#include "specular/tlm/register_fields.h"
#include "specular/tlm/register_map.h"

namespace specular {
namespace firmware_header {

namespace {

constexpr const char* prefix = "SPECULAR_";

std::string hex(std::uint32_t value, int digits) {
  std::ostringstream s;
  s << "0x" << std::hex << std::uppercase << std::setw(digits) << std::setfill('0') << value
    << "u";
  return s.str();
}
std::string dec(std::uint32_t value) { return std::to_string(value) + "u"; }

/// The C name of an access kind (SPECULAR_ACCESS_<name>).
const char* access_name(Access access) {
  switch (access) {
    case Access::read_only: return "RO";
    case Access::read_write: return "RW";
    case Access::write_1_to_clear: return "W1C";
    case Access::self_clearing: return "WSC";
  }
  return "?";
}
const char* access_meaning(Access access) {
  switch (access) {
    case Access::read_only: return "read-only: a write is refused (STATUS.CAUSE READ_ONLY)";
    case Access::read_write: return "read/write: a value out of range is refused, never clamped";
    case Access::write_1_to_clear: return "reads state; writing 1 to a flag clears it";
    case Access::self_clearing: return "a write acts (START); reads return 0";
  }
  return "?";
}

/// Text inside a C comment cannot close it.
std::string comment_safe(std::string text) {
  for (std::size_t at = text.find("*/"); at != std::string::npos; at = text.find("*/"))
    text.replace(at, 2, "* /");
  return text;
}

/// `text` as comment lines " * ...", wrapped before 90 columns.
std::string comment_lines(const std::string& text, const std::string& lead = " * ") {
  std::istringstream words(comment_safe(text));
  std::string out, line, word;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > 86) {
      out += lead + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += lead + line + "\n";
  return out;
}

/// `#define NAME VALUE` with the value in column 48 and its Doxygen trailing comment
/// (`/**< ... */`: the API reference, docs/api/, requires one on every macro).
std::string define(const std::string& name, const std::string& value,
                   const std::string& comment) {
  std::string line = "#define " + name + " ";
  if (line.size() < 48) line.append(48 - line.size(), ' ');
  line += value;
  line += "  /**< " + comment_safe(comment) + " */";
  return line + "\n";
}

/// Opens a Doxygen member group: a heading in the reference, `text` below it.
std::string group_open(const std::string& title, const std::string& text = "") {
  return "/** \\name " + comment_safe(title) + "\n" + comment_lines(text, " * ") + " * @{\n */\n";
}
const char* group_close = "/** @} */\n";

std::string reg_name(Reg reg) { return std::string(prefix) + info(reg).name; }

void print_access_kinds(std::ostream& out) {
  out << group_open("Access kinds",
                    "The values of `SPECULAR_<REG>_ACCESS` and `SPECULAR_<REG>_<FIELD>_ACCESS`.");
  for (Access a : {Access::read_only, Access::read_write, Access::write_1_to_clear,
                   Access::self_clearing})
    out << define(std::string(prefix) + "ACCESS_" + access_name(a),
                  dec(static_cast<std::uint32_t>(a)), access_meaning(a));
  out << group_close << "\n";
}

void print_fields(std::ostream& out, Reg reg) {
  for (const FieldInfo& f : register_fields) {
    if (f.reg != reg) continue;
    const std::string field = reg_name(reg) + "_" + f.name;
    const std::string dotted = std::string(info(reg).name) + "." + f.name;
    const std::string bits = f.width == 1 ? "[" + std::to_string(f.shift) + "]"
                                          : "[" + std::to_string(f.shift + f.width - 1) + ":" +
                                                std::to_string(f.shift) + "]";
    out << "/* " << info(reg).name << bits << " " << f.name << ": " << comment_safe(f.description)
        << " */\n";
    out << define(field + "_SHIFT", dec(static_cast<std::uint32_t>(f.shift)),
                  "Bit position of " + dotted + " (" + info(reg).name + bits + "): " + f.description)
        << define(field + "_WIDTH", dec(static_cast<std::uint32_t>(f.width)), "Bits in " + dotted)
        << define(field + "_MASK", hex(f.mask(), 8), dotted + "'s bits, in place")
        << define(field + "_ACCESS", std::string(prefix) + "ACCESS_" + access_name(f.access),
                  "Access kind of " + dotted);
    const std::vector<FieldValue> values = field_values(f.values);
    for (const FieldValue& v : values)
      out << define(field + "_" + v.name, dec(v.value),
                    v.description.empty() ? dotted + " value " + v.name : v.description);
    if (!values.empty()) out << define(field + "_COUNT", dec(static_cast<std::uint32_t>(values.size())),
                                       "number of values above");
  }
}

void print_register(std::ostream& out, const RegisterInfo& row) {
  const std::string name = std::string(prefix) + row.name;
  const std::string offset = hex(row.offset, 4);
  out << group_open(offset.substr(0, offset.size() - 1) + " " + row.name + " (" +
                        to_string(row.access) +
                        (row.words > 1 ? ", a window of " + std::to_string(row.words) + " words"
                                       : std::string()) +
                        ")",
                    row.description);
  out << define(name + "_OFFSET", hex(row.offset, 4),
                std::string("Byte offset of ") + row.name + " from the IP's base")
      << define(name + "_ACCESS", std::string(prefix) + "ACCESS_" + access_name(row.access),
                std::string("Access kind of ") + row.name)
      << define(name + "_RESET", hex(row.reset, 8),
                std::string(row.name) + " after reset" +
                    (row.reg == Reg::config ? ": the default configuration's word" : "") +
                    (row.reg == Reg::batch_capacity ? " on the TLM-2.0 targets; specular_ip_axi reads 0"
                     : row.reg == Reg::config || row.reg == Reg::pin19_h || row.reg == Reg::pin20_a
                         ? std::string(" (specular_ip_axi: its parameter ") + row.name + "_VALUE)"
                         : ""));
  if (row.words > 1)
    out << define(name + "_WORDS", dec(row.words), std::string("32-bit words in ") + row.name)
        << define(name + "_SIZE", hex(4 * row.words, 4), std::string("Bytes in ") + row.name);
  if (row.reg == Reg::operands)
    for (std::uint32_t w = 0; w < operand_words; ++w)
      out << define(name + "_" + info(operand_register(w)).name + "_WORD", dec(w),
                    "word index: the register " + std::string(info(operand_register(w)).name));
  if (row.reg == Reg::results)
    for (std::uint32_t w = 0; w < row.words; ++w)
      out << define(name + "_" + info(result_register(w)).name + "_WORD", dec(w),
                    "word index: the register " + std::string(info(result_register(w)).name));
  if (row.reg == Reg::batch_out)
    out << define(name + "_WORDS_PER_OPERATION",
                  dec(info(Reg::batch_out).words / info(Reg::batch_cos).words),
                  "OUT_R, OUT_G, OUT_B of operation i at words 3i, 3i+1, 3i+2");
  print_fields(out, row.reg);
  out << group_close << "\n";
}

}  // namespace

std::string text() {
  std::ostringstream out;
  const Formats defaults{};
  out << "/** \\file specular_regs.h\n"
         " * \\brief The register map of the specular colour intensity IP (patent UA 59965 U) for\n"
         " * firmware: every register's offset, access and reset value, the fields with their\n"
         " * shift, width, mask and values, the window sizes and the interrupt's rules.\n"
         " *\n"
         " * GENERATED by specular_firmware_header from modules/include/specular/tlm/register_map.h\n"
         " * and register_fields.h (the one source, as the docs' tables are): edit the map, not\n"
         " * this file. A test fails on any difference between the two.\n"
         " *\n"
         " * Plain C99 and C++ alike, freestanding: nothing beyond <stdint.h>. Every constant is\n"
         " * unsigned. Names: `SPECULAR_<REG>_OFFSET` (bytes from the IP's base), _ACCESS, _RESET,\n"
         " * and for a window _WORDS and _SIZE; `SPECULAR_<REG>_<FIELD>_SHIFT`, _WIDTH, _MASK (in\n"
         " * place), _ACCESS; `SPECULAR_<REG>_<FIELD>_<VALUE>` for an enumerated field. Registers\n"
         " * are 32 bits wide, accessed as aligned words (1- and 2-byte reads work too; see\n"
         " * docs/integration.md section 3).\n"
         " */\n"
         "#ifndef SPECULAR_SPECULAR_REGS_H\n"
         "#define SPECULAR_SPECULAR_REGS_H\n\n"
         "#include <stdint.h>\n\n";
  out << group_open("The IP")
      << define(std::string(prefix) + "DEVICE_ID", hex(device_id, 8), "ID reads this (patent UA 59965 U)")
      << define(std::string(prefix) + "MAP_VERSION", hex(map_version, 8), "VERSION reads this: (major << 16) | minor")
      << define(std::string(prefix) + "MAP_VERSION_MAJOR", dec(map_version >> 16),
                "a driver refuses another major version")
      << define(std::string(prefix) + "MAP_SIZE", hex(map_size, 4),
                "bytes the IP decodes from its base: give it a window this size, aligned to it")
      << define(std::string(prefix) + "REGISTER_COUNT", dec(static_cast<std::uint32_t>(register_count)),
                "rows of the map (registers and windows)")
      << define(std::string(prefix) + "BATCH_CAPACITY", dec(batch_capacity),
                "operations per batch on the TLM-2.0 targets (their BATCH_CAPACITY, BATCH_COS's "
                "words: the most an IP of this map holds); not every IP's: specular_ip_axi reads 0 "
                "(no windows), so a driver reads BATCH_CAPACITY")
      << group_close << "\n"
      << group_open("Operand ranges", "Larger values are refused (STATUS.ERROR), never clamped.")
      << define(std::string(prefix) + "N_MIN", dec(n_min), "smallest specular exponent n")
      << define(std::string(prefix) + "N_MAX", dec(n_max), "largest specular exponent n")
      << define(std::string(prefix) + "COS_MAX_DEFAULT", hex(static_cast<std::uint32_t>(defaults.cos.one()), 8),
                "cos = 1.0 in U1." + std::to_string(defaults.widths.cos_frac_bits) +
                    ", the default; in general 1 << CONFIG.COS_FRAC_BITS")
      << define(std::string(prefix) + "RGB_MAX_DEFAULT", dec(static_cast<std::uint32_t>(defaults.rgb.max_code())),
                "largest R, G, B code of the default format; in general (1 << CONFIG.RGB_BITS) - 1")
      << group_close << "\n";
  print_access_kinds(out);
  out << "/* ---- Registers and windows, in address order ---- */\n\n";
  for (const RegisterInfo& row : register_map) print_register(out, row);
  out << "/** \\name The interrupt (done_irq)\n"
      << comment_lines(
             "done_irq is a LEVEL, high while STATUS.DONE is set: from the end of an operation "
             "(CONTROL.START, an OPERANDS burst whose last word is START, or a BATCH_COS write) "
             "until software writes 1 to STATUS.DONE (W1C) or the next operation starts. A "
             "handler acknowledges by writing SPECULAR_IRQ_ACK_VALUE to SPECULAR_IRQ_ACK_OFFSET "
             "before it returns, or it is entered again, as for any level-sensitive line. "
             "STATUS.DONE is always current in the CPU's own time, so polling it needs no "
             "interrupt. In a virtual platform with temporal decoupling, the line's edges come "
             "at the CPU's annotated times and the CPU sees them only when it yields (at the end "
             "of its quantum or in wfi): a DONE set and cleared inside one quantum may show no "
             "pulse on the line (STATUS always shows it).")
      << " * @{\n */\n"
      << define(std::string(prefix) + "IRQ_LEVEL_SENSITIVE", "1u", "done_irq is a level, not a pulse")
      << define(std::string(prefix) + "IRQ_STATUS_MASK", reg_name(Reg::status) + "_DONE_MASK",
                "the STATUS bit whose level done_irq is")
      << define(std::string(prefix) + "IRQ_ACK_OFFSET", reg_name(Reg::status) + "_OFFSET",
                "Acknowledge: write SPECULAR_IRQ_ACK_VALUE at this offset (STATUS)")
      << define(std::string(prefix) + "IRQ_ACK_VALUE", reg_name(Reg::status) + "_DONE_MASK",
                "Written at SPECULAR_IRQ_ACK_OFFSET (W1C): the level falls")
      << group_close << "\n"
      << group_open("Field helpers", "FIELD is a field's prefix such as SPECULAR_STATUS_CAUSE.")
      << define(std::string(prefix) + "FIELD_GET(FIELD, word)",
                "((uint32_t)(((uint32_t)(word) & FIELD##_MASK) >> FIELD##_SHIFT))",
                "The value of field FIELD in the register word `word`, shifted down")
      << define(std::string(prefix) + "FIELD_PREP(FIELD, value)",
                "((uint32_t)(((uint32_t)(value) << FIELD##_SHIFT) & FIELD##_MASK))",
                "`value` placed in field FIELD's bits (to OR into a register word)")
      << group_close << "\n#endif /* SPECULAR_SPECULAR_REGS_H */\n";
  return out.str();
}

}  // namespace firmware_header
}  // namespace specular
