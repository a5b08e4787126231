// specular_firmware_header: prints the firmware C header from the register map
// (firmware_header.h), or checks or rewrites the committed copy (--help: the options
// and exit statuses).
//
//   specular_firmware_header --print | --check SOURCE_DIR | --write SOURCE_DIR
//                            | --c-header FILE
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "cli.h"
#include "firmware_header.h"
#include "usage_error.h"

namespace {

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
  specular::cli::Command app{"Prints the firmware C header from the register map, or checks or rewrites the committed copy.",
                             "specular_firmware_header"};
  specular::cli::house_rules(app, "Exit status: 0 done (--check: the committed header is the generated one), "
                                  "1 it differs, 2 bad arguments or an unreadable or unwritable file.");
  bool print = false;
  std::string check_dir, write_dir, c_header;
  specular::cli::Command* mode = app.add_option_group("mode", "exactly one of");
  mode->add_flag("--print", print, "write the header to standard output");
  mode->add_option("--check", check_dir, "exit 1 unless DIR/firmware/include/specular/specular_regs.h is this header")
      ->type_name("DIR");
  mode->add_option("--write", write_dir, "write it there")->type_name("DIR");
  mode->add_option("--c-header", c_header, "write it to FILE")->type_name("FILE");
  mode->require_option(1);
  return specular::cli::run(app, argc, argv, [&] {
    if (print) {
      std::cout << fh::text();
      return 0;
    }
    const std::string path = !c_header.empty() ? c_header
                             : !check_dir.empty() ? check_dir + "/" + fh::path
                                                  : write_dir + "/" + fh::path;
    if (!check_dir.empty()) {
      std::ifstream in(path, std::ios::binary);
      if (!in) throw specular::tb::UsageError("cannot read '" + path + "'");
      std::ostringstream s;
      s << in.rdbuf();
      if (s.str() == fh::text()) return 0;
      std::cerr << path << " differs from the register map; run specular_firmware_header --write "
                << check_dir << "\n";
      return 1;
    }
    if (!write_file(path, fh::text())) throw specular::tb::UsageError("cannot write '" + path + "'");
    std::cout << path << " written\n";
    return 0;
  });
}
