// specular_firmware_header: prints the firmware C header from the register map
// (firmware_header.h), or checks or rewrites the committed copy.
//
//   specular_firmware_header --print | --check SOURCE_DIR | --write SOURCE_DIR
//                            | --c-header FILE
//
// Exit status: 0 done (--check: the committed header is the generated one), 1 it
// differs, 2 bad arguments or an unreadable or unwritable file.
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "firmware_header.h"

namespace {

const char* usage =
    "usage: specular_firmware_header --print | --check SOURCE_DIR | --write SOURCE_DIR | --c-header FILE\n"
    "  --print          write the header to standard output\n"
    "  --check DIR      exit 1 unless DIR/firmware/include/specular/specular_regs.h is this header\n"
    "  --write DIR      write it there\n"
    "  --c-header FILE  write it to FILE\n";

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  return static_cast<bool>(out);
}

}  // namespace

// The library links SystemC, whose shared object asks for sc_main wherever the linker
// keeps it (the sanitizer builds do); this tool never starts a simulation.
extern "C" int sc_main(int, char**) { return 0; }

int main(int argc, char** argv) {
  namespace fh = specular::firmware_header;
  const std::string mode = argc >= 2 ? argv[1] : "";
  if (mode == "--help") {
    std::cout << usage;
    return 0;
  }
  if (mode == "--print" && argc == 2) {
    std::cout << fh::text();
    return 0;
  }
  if ((mode != "--check" && mode != "--write" && mode != "--c-header") || argc != 3) {
    std::cerr << "specular_firmware_header: error: expected --print, --check DIR, --write DIR or "
                 "--c-header FILE\n"
              << usage;
    return 2;
  }
  const std::string path = mode == "--c-header" ? argv[2] : std::string(argv[2]) + "/" + fh::path;
  if (mode == "--check") {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      std::cerr << "specular_firmware_header: error: cannot read '" << path << "'\n";
      return 2;
    }
    std::ostringstream s;
    s << in.rdbuf();
    if (s.str() == fh::text()) return 0;
    std::cerr << path << " differs from the register map; run specular_firmware_header --write "
              << argv[2] << "\n";
    return 1;
  }
  if (!write_file(path, fh::text())) {
    std::cerr << "specular_firmware_header: error: cannot write '" << path << "'\n";
    return 2;
  }
  std::cout << path << " written\n";
  return 0;
}
