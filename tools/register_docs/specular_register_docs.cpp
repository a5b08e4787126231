// specular_register_docs: prints the docs' register tables from the register map, or
// checks or rewrites them in place between their marker comments (register_docs.h);
// --help: the options and exit statuses.
//
//   specular_register_docs --print | --check SOURCE_DIR | --write SOURCE_DIR
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "cli.h"
#include "register_docs.h"
#include "usage_error.h"

namespace {

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
  specular::cli::Command app{"Prints the docs' register tables from the register map, or checks or rewrites them in place.",
                             "specular_register_docs"};
  specular::cli::house_rules(app, "Exit status: 0 done (--check: every table matches), 1 a table differs or its "
                                  "markers are missing, 2 bad arguments or an unreadable file.");
  bool print = false;
  std::string check_dir, write_dir;
  specular::cli::Command* mode = app.add_option_group("mode", "exactly one of");
  mode->add_flag("--print", print, "write every generated table to standard output");
  mode->add_option("--check", check_dir, "exit 1 unless DIR's docs carry exactly these tables")->type_name("DIR");
  mode->add_option("--write", write_dir, "replace the tables between their markers in DIR's docs")->type_name("DIR");
  mode->require_option(1);
  return specular::cli::run(app, argc, argv, [&]() -> int {
    if (print) {
      for (const GeneratedTable& t : generated_tables())
        std::cout << t.file << ":\n" << begin_marker(t.name) << region_text(t) << end_marker(t.name) << "\n";
      return 0;
    }
    const bool check = !check_dir.empty();
    const std::string root = check ? check_dir : write_dir;
    int status = 0;
    for (const GeneratedTable& t : generated_tables()) {
      const std::string path = root + "/" + t.file;
      std::string doc;
      if (!slurp(path, doc)) throw specular::tb::UsageError("cannot read '" + path + "'");
      const auto current = region(doc, t.name);
      if (!current) {
        std::cerr << path << ": the markers of '" << t.name << "' are missing or repeated; add\n"
                  << begin_marker(t.name) << end_marker(t.name);
        status = 1;
        continue;
      }
      if (*current == region_text(t)) continue;
      if (check) {
        std::cerr << path << ": table '" << t.name << "' differs from the register map; run "
                  << "specular_register_docs --write " << root << "\n";
        status = 1;
        continue;
      }
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out << *with_region(doc, t.name, region_text(t));
      if (!out) throw specular::tb::UsageError("cannot write '" + path + "'");
      std::cout << path << ": table '" << t.name << "' rewritten\n";
    }
    return status;
  });
}
