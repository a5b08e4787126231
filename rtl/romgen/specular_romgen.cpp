// specular_romgen: the ROM images of the RTL twin, written once from the C++ tables.
//
// ROM 5 and ROM 38 of rtl/ read `$readmemh` images in Icarus, Yosys and the silicon flow
// (the verilated twin is filled from the same words in C++, twin/src/rom_loader.h). They
// come from the tables the core and the SystemC model use (specular::rom_images), for the
// widths given: never hand-copied. The default widths' images are committed beside the
// Verilog that reads them (rtl/sources.cmake), and test rtl_rom_images_current fails when
// this tool would write them differently; other widths are written in the build. The
// same tool checks a dump the RTL wrote while reading its ROMs through their ports
// (rtl/tb/rom_read_tb.v), so a test proves every word the RTL reads equals the table's.
//
//   specular_romgen --out-dir DIR [--bank-bits B] [--width NAME=VALUE]...
//       writes DIR/rom5.hex (2^rom5_addr_bits words) and DIR/rom38.hex (2^B banks of
//       2^n_bits words; bank b = Normalisation value b, unused banks zero), DIR/pins.hex
//       and DIR/exp2.hex (variant exp2's exp2 unit, rtl/design_space/exp2_unit.v), DIR/recip.hex
//       (variant schlick's reciprocal table, rtl/design_space/reciprocal_nr.v)
//   specular_romgen --check DUMP [--bank-bits B] [--width NAME=VALUE]...
//       compares every "rom5 BUS LOG2" and "rom38 BANK N K" line (hex) of DUMP with the
//       tables; exit 1 on the first difference or when an address was never read
// Exit status: 0 done, 1 a difference (--check), 2 bad option or file.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.h"
#include "parse_values.h"
#include "specular/arith.h"
#include "specular/rom38_banks.h"
#include "specular/rom_images.h"
#include "specular/constants.h"
#include "specular/format.h"
#include "specular/variants/exp2_unit.h"
#include "specular/variants/reciprocal.h"
#include "usage_error.h"

namespace {

using specular::code_t;
using specular::Formats;
using specular::Widths;

using specular::tb::UsageError;

/// --width NAME=VALUE into `widths` (the names and ranges of specular::set_width).
void set_width(Widths& widths, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw UsageError("--width: '" + assignment + "' is not NAME=VALUE");
  const std::string name = assignment.substr(0, eq);
  const long long value = specular::tb::parse_integer(assignment.substr(eq + 1), "--width " + name, "[0, 63]");
  try {
    specular::set_width(widths, name, static_cast<int>(value));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--width: ") + e.what());
  }
}

struct Options {
  Widths widths;
  int bank_bits = specular::rom38_bank_bits;
  std::string out_dir;
  std::string check_path;
};

/// Declares the options on `app` (run_support/cli.h), each writing into `o`.
void add_options(specular::cli::Command& app, Options& o) {
  specular::cli::Command* mode = app.add_option_group("mode", "exactly one of");
  mode->add_option("--out-dir", o.out_dir,
                   "write DIR/rom5.hex (2^rom5_addr_bits words), DIR/rom38.hex (2^B banks of 2^n_bits "
                   "words; bank b = Normalisation value b, unused banks zero), DIR/pins.hex, DIR/exp2.hex "
                   "(variant exp2's exp2 unit) and DIR/recip.hex (variant schlick's reciprocal table)")
      ->type_name("DIR");
  mode->add_option("--check", o.check_path,
                   "compare every \"rom5 BUS LOG2\" and \"rom38 BANK N K\" line (hex) of DUMP with the "
                   "tables; exit 1 on the first difference or when an address was never read")
      ->type_name("DUMP");
  mode->require_option(1);
  app.add_option("--bank-bits", o.bank_bits, "ROM 38's bank address bits (one bank per constants x normalisation pair)")
      ->type_name("B")
      ->capture_default_str()
      ->check(specular::cli::integer_in(specular::rom38_bank_bits, 8));
  app.add_option_function<std::vector<std::string>>(
         "--width",
         [&o](const std::vector<std::string>& values) {
           for (const std::string& v : values) set_width(o.widths, v);
         },
         "a bus width other than docs/design.md's, once per width")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
}

/// One word per line, as many hex digits as the width needs.
void write_image(const std::string& path, const std::string& comment, int width,
                 const std::vector<std::uint64_t>& words) {
  std::ofstream out(path);
  if (!out) throw UsageError("cannot write '" + path + "'");
  out << "// " << comment << " (written by specular_romgen; do not edit)\n";
  const int digits = (width + 3) / 4;
  char line[32];
  for (std::uint64_t word : words) {
    std::snprintf(line, sizeof line, "%0*llx\n", digits, static_cast<unsigned long long>(word));
    out << line;
  }
  if (!out.flush()) throw UsageError("cannot write '" + path + "'");
}

void write_images(const Options& o) {
  const Formats f(o.widths);
  const specular::RomImages images = specular::rom_images(f, o.bank_bits);
  write_image(o.out_dir + "/rom5.hex",
              "ROM 5 mantissa table: " + std::to_string(images.rom5.size()) + " words x " +
                  std::to_string(o.widths.rom5_word_bits) + " bits",
              o.widths.rom5_word_bits, images.rom5);
  write_image(o.out_dir + "/rom38.hex",
              "ROM 38 s*K(n): " + std::to_string(1 << o.bank_bits) + " banks (bank = 4 * constants + " +
                  "normalisation; " + std::to_string(images.rom38_banks_filled) + " filled, others zero) x " +
                  std::to_string(f.rom38_words()) + " words x " + f.rom38.name(),
              f.rom38.width(), images.rom38);

  // Pins 19 (h) and 20 (a) per constants policy, for testbenches that tie them off as
  // the pin harness does: word 2c = h, word 2c + 1 = a of Constants value c (zero when
  // the bus cannot hold the constant; the device refuses that policy then).
  std::vector<std::uint64_t> words;
  for (const specular::Constants constants : specular::every_constants) {
    if (words.size() != 2 * static_cast<std::size_t>(constants)) throw std::logic_error("constants order");
    std::uint64_t h = 0, a = 0;
    try {
      h = static_cast<std::uint64_t>(specular::pin19_code(f, constants)) &
          ((std::uint64_t{1} << f.mux4.width()) - 1);
      a = static_cast<std::uint64_t>(specular::pin20_code(f, constants)) &
          ((std::uint64_t{1} << f.reg9.width()) - 1);
    } catch (const std::invalid_argument&) {
    }
    words.push_back(h);
    words.push_back(a);
  }
  write_image(o.out_dir + "/pins.hex",
              "pins 19 (h, " + f.mux4.name() + ") and 20 (a, " + f.reg9.name() +
                  "): words 2c, 2c+1 for Constants value c",
              64, words);

  // Variant exp2's exp2 unit (rtl/design_space/exp2_unit.v): 2^(i/2^A) and the difference to the next
  // word. Its organisation is the unit's own, the same in every width set.
  const specular::variants::Exp2Table exp2;
  write_image(o.out_dir + "/exp2.hex",
              "exp2 unit: " + std::to_string(exp2.words().size()) + " words x " +
                  std::to_string(exp2.word_bits()) + " bits {2^(i/2^A) - 1 on " +
                  std::to_string(exp2.organisation().value_frac_bits) + " fraction bits, difference to the next on " +
                  std::to_string(exp2.delta_bits()) + " bits}",
              exp2.word_bits(), exp2.words());

  // Variant schlick's reciprocal table (rtl/design_space/reciprocal_nr.v): the same at every width set.
  const specular::variants::ReciprocalNr reciprocal;
  write_image(o.out_dir + "/recip.hex",
              "variant schlick: 1/m table, " + std::to_string(reciprocal.words().size()) + " words x U0." +
                  std::to_string(specular::variants::ReciprocalNr::word_bits),
              specular::variants::ReciprocalNr::word_bits,
              std::vector<std::uint64_t>(reciprocal.words().begin(), reciprocal.words().end()));
}

std::uint64_t parse_hex(const std::string& text, const std::string& where) {
  std::size_t used = 0;
  std::uint64_t value = 0;
  try {
    value = std::stoull(text, &used, 16);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) throw UsageError(where + ": '" + text + "' is not hex");
  return value;
}

/// A code read back as `width` bits, sign-extended when the bus is signed.
code_t as_code(std::uint64_t bits, const specular::FixedFormat& format) {
  return specular::arith::wrap(format, static_cast<code_t>(bits));
}

int check_dump(const Options& o) {
  const Formats f(o.widths);
  const specular::arith::Rom5Table rom5(f);
  const auto rom38 = specular::rom38_bank_tables(f, o.bank_bits);
  const std::size_t bank_words = static_cast<std::size_t>(f.rom38_words());
  const std::size_t rom38_total = bank_words << o.bank_bits;

  std::ifstream in(o.check_path);
  if (!in) throw UsageError("--check: cannot read '" + o.check_path + "'");
  // Which mantissa words and ROM 38 words the dump proved, by address.
  std::vector<bool> rom5_seen(rom5.words().size(), false), rom38_seen(rom38_total, false);
  long lines = 0;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string kind, a, b, c;
    if (!(fields >> kind)) continue;
    const std::string where = o.check_path + ":" + std::to_string(lines + 1);
    ++lines;
    if (kind == "rom5" && fields >> a >> b) {
      const code_t bus = as_code(parse_hex(a, where), f.reg9);
      const code_t got = as_code(parse_hex(b, where), f.log2);
      const code_t want = rom5.log2(bus);
      if (got != want) {
        std::cerr << where << ": ROM 5 at bus " << bus << " gave " << got << ", the table " << want << '\n';
        return 1;
      }
      if (bus > 0) {  // the word this bus addresses (as the table's lookup finds it)
        const int msb = 63 - __builtin_clzll(static_cast<std::uint64_t>(bus));
        const std::uint64_t aligned = (static_cast<std::uint64_t>(bus) << (63 - msb)) << 1;
        rom5_seen[aligned >> (64 - o.widths.rom5_addr_bits)] = true;
      }
    } else if (kind == "rom38" && fields >> a >> b >> c) {
      const std::size_t bank = parse_hex(a, where), n = parse_hex(b, where);
      const code_t got = as_code(parse_hex(c, where), f.rom38);
      if (bank >= (std::size_t{1} << o.bank_bits) || n >= bank_words)
        throw UsageError(where + ": ROM 38 address out of range");
      const code_t want = rom38[bank] ? rom38[bank]->k(static_cast<code_t>(n)) : 0;
      if (got != want) {
        std::cerr << where << ": ROM 38 bank " << bank << " n " << n << " gave " << got
                  << ", the table " << want << '\n';
        return 1;
      }
      rom38_seen[bank * bank_words + n] = true;
    } else {
      throw UsageError(where + ": expected 'rom5 BUS LOG2' or 'rom38 BANK N K', got '" + line + "'");
    }
  }
  std::size_t rom5_read = 0, rom38_read = 0;
  for (bool seen : rom5_seen) rom5_read += seen;
  for (bool seen : rom38_seen) rom38_read += seen;
  std::cout << "specular_romgen --check: " << lines << " reads; ROM 5 words read " << rom5_read << " of "
            << rom5_seen.size() << ", ROM 38 words read " << rom38_read << " of " << rom38_total
            << '\n';
  if (rom5_read != rom5_seen.size() || rom38_read != rom38_total) {
    std::cerr << "specular_romgen --check: the dump does not read every ROM word\n";
    return 1;
  }
  std::cout << "specular_romgen --check: every word equals the C++ table's\n";
  return 0;
}

}  // namespace

// The library links SystemC, whose shared object asks for sc_main wherever the linker
// keeps it (the sanitizer builds do); this tool never starts a simulation.
extern "C" int sc_main(int, char**) { return 0; }

int main(int argc, char** argv) {
  specular::cli::Command app{"The ROM images of the RTL twin, written once from the C++ tables, or a dump the RTL wrote\n"
                             "checked against them.",
                             "specular_romgen"};
  specular::cli::house_rules(app, "Exit status: 0 done, 1 a difference (--check), 2 bad option or file, 3 internal.");
  Options o;
  add_options(app, o);
  return specular::cli::run(app, argc, argv, [&] {
    try {
      o.widths.validate();
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--width: ") + e.what());
    }
    try {
      if (!o.check_path.empty()) return check_dump(o);
      write_images(o);
      return 0;
    } catch (const UsageError&) {
      throw;  // cli::run: exit 2
    } catch (const std::exception& e) {
      std::cerr << "specular_romgen: internal error: " << e.what() << '\n';
      return 3;
    }
  });
}
