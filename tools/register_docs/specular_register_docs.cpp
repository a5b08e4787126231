// specular_register_docs: prints the docs' register tables from the register map, or
// checks or rewrites them in place between their marker comments (register_docs.h).
//
//   specular_register_docs --print | --check SOURCE_DIR | --write SOURCE_DIR
//
// Exit status: 0 done (--check: every table matches), 1 a table differs or its markers
// are missing, 2 bad arguments or an unreadable file.
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "register_docs.h"

namespace {

const char* usage =
    "usage: specular_register_docs --print | --check SOURCE_DIR | --write SOURCE_DIR\n"
    "  --print       write every generated table to standard output\n"
    "  --check DIR   exit 1 unless DIR's docs carry exactly these tables\n"
    "  --write DIR   replace the tables between their markers in DIR's docs\n";

bool slurp(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return true;
}

}  // namespace

// The library links SystemC, whose shared object asks for sc_main wherever the linker
// keeps it (the sanitizer builds do); this tool never starts a simulation.
extern "C" int sc_main(int, char**) { return 0; }

int main(int argc, char** argv) {
  using namespace specular::register_docs;
  const std::string mode = argc >= 2 ? argv[1] : "";
  if (mode == "--help") {
    std::cout << usage;
    return 0;
  }
  if (mode == "--print" && argc == 2) {
    for (const GeneratedTable& t : generated_tables())
      std::cout << t.file << ":\n" << begin_marker(t.name) << region_text(t) << end_marker(t.name) << "\n";
    return 0;
  }
  if ((mode != "--check" && mode != "--write") || argc != 3) {
    std::cerr << "specular_register_docs: error: expected --print, --check DIR or --write DIR\n"
              << usage;
    return 2;
  }
  const std::string root = argv[2];
  int status = 0;
  for (const GeneratedTable& t : generated_tables()) {
    const std::string path = root + "/" + t.file;
    std::string doc;
    if (!slurp(path, doc)) {
      std::cerr << "specular_register_docs: error: cannot read '" << path << "'\n";
      return 2;
    }
    const auto current = region(doc, t.name);
    if (!current) {
      std::cerr << path << ": the markers of '" << t.name << "' are missing or repeated; add\n"
                << begin_marker(t.name) << end_marker(t.name);
      status = 1;
      continue;
    }
    if (*current == region_text(t)) continue;
    if (mode == "--check") {
      std::cerr << path << ": table '" << t.name << "' differs from the register map; run "
                << "specular_register_docs --write " << root << "\n";
      status = 1;
      continue;
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << *with_region(doc, t.name, region_text(t));
    if (!out) {
      std::cerr << "specular_register_docs: error: cannot write '" << path << "'\n";
      return 2;
    }
    std::cout << path << ": table '" << t.name << "' rewritten\n";
  }
  return status;
}
