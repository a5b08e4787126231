// specular_ip_export: the IP's descriptions for SoC tools, written from the register map
// (register_map.h, register_fields.h) and the Verilog tops' headers (docs/ipxact.md):
//
//   specular_ip_export --source-dir DIR [--version V] [--libdir D]
//                      [--ipxact FILE] [--systemrdl FILE] [--json FILE]
//
// --help lists the options (declared in main through run_support/cli.h).
// FILE "-" is standard output. Exit status: 0 written, 2 bad arguments, an unreadable
// Verilog file or an unwritable output.
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "cli.h"
#include "ipxact_writer.h"
#include "map_json.h"
#include "systemrdl_writer.h"
#include "verilog_header.h"
#include "verilog_regblock.h"

#ifndef SPECULAR_PACKAGE_VERSION
#error "SPECULAR_PACKAGE_VERSION: the build passes the package's version"
#endif

namespace {

/// --set's list: NAME=VALUE pairs, VALUE decimal or 0x hex. Throws std::invalid_argument
/// naming the bad pair.
std::map<std::string, std::int64_t> parse_settings(const std::string& text) {
  std::map<std::string, std::int64_t> settings;
  std::string::size_type start = 0;
  while (start <= text.size()) {
    const std::string::size_type comma = text.find(',', start);
    const std::string pair = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::string::size_type eq = pair.find('=');
    std::size_t used = 0;
    long long value = 0;
    try {
      if (eq == std::string::npos || eq == 0) throw std::invalid_argument(pair);
      value = std::stoll(pair.substr(eq + 1), &used, 0);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != pair.size() - eq - 1)
      throw std::invalid_argument("--set: '" + pair + "' is not NAME=VALUE (VALUE decimal or 0x hex)");
    settings[pair.substr(0, eq)] = value;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return settings;
}

bool write(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    return static_cast<bool>(std::cout);
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) {
    std::cerr << "specular_ip_export: error: cannot write '" << path << "'\n";
    return false;
  }
  return true;
}

const char* const axi_description =
    "The whole IP in Verilog: an AMBA AXI4-Lite slave with the generated register block "
    "and the synchronous device, done_irq (docs/rtl_ip.md)";

/// Writes what `options` ask for; the options as the command line gave them.
int export_ip(std::map<std::string, std::string>& options) {
  using namespace specular::ip_export;
  if (!options.count("--ipxact") && !options.count("--systemrdl") && !options.count("--json") &&
      !options.count("--bus-dir") && !options.count("--verilog") && !options.count("--ipxact-resolved")) {
    std::cerr << "specular_ip_export: error: nothing to write: give --ipxact, --systemrdl, --json, "
                 "--bus-dir, --verilog or --ipxact-resolved\n";
    return 2;
  }
  if (options.count("--set") && !options.count("--ipxact-resolved")) {
    std::cerr << "specular_ip_export: error: --set applies to --ipxact-resolved only\n";
    return 2;
  }
  if ((options.count("--ipxact") || options.count("--ipxact-resolved")) && !options.count("--source-dir")) {
    std::cerr << "specular_ip_export: error: --ipxact and --ipxact-resolved need --source-dir (the Verilog tops)\n";
    return 2;
  }
  bool ok = true;
  if (options.count("--verilog")) ok = write(options["--verilog"], verilog_register_block()) && ok;
  if (options.count("--json")) ok = write(options["--json"], register_map_json()) && ok;
  if (options.count("--bus-dir")) {
    ok = write(options["--bus-dir"] + "/" + bus_definition_file, ipxact_bus_definition()) && ok;
    ok = write(options["--bus-dir"] + "/" + abstraction_definition_file,
               ipxact_abstraction_definition()) && ok;
  }
  if (options.count("--systemrdl"))
    ok = write(options["--systemrdl"], systemrdl_addrmap(options["--version"])) && ok;
  if (options.count("--ipxact")) {
    struct Component {
      const char* top;  // relative to rtl/
      const char* name;
      const char* description;
      bool systemc;
    };
    const Component components[] = {
        {"device/specular_device", "specular_unit",
         "Specular colour intensity device of patent UA 59965 U: the SystemC TLM-2.0 targets and "
         "the drawn device's Verilog top (README.md)", true},
        {"device/specular_device_sync", "specular_device_sync",
         "The synchronous variant of the device of UA 59965 U (one clock, enables; docs/rtl.md): "
         "its Verilog top with pins 17-35", false},
        {"ip/specular_ip_axi", "specular_ip_axi", axi_description, false},
    };
    const std::string main_file = options["--ipxact"];
    const std::string::size_type slash = main_file.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "" : main_file.substr(0, slash + 1);
    const std::string rtl = options["--source-dir"] + "/rtl";
    try {
      // The folders of rtl/sources.cmake: the device's blocks, the primitives, the
      // design-space tops (read too: a module name must be unique across all three).
      // and ip/: the whole IP behind its AXI4-Lite slave (docs/rtl_ip.md)
      const auto modules = read_modules({rtl + "/device", rtl + "/primitives", rtl + "/design_space",
                                         rtl + "/ip"});
      for (const Component& c : components) {
        ComponentFacts facts;
        facts.name = c.name;
        facts.description = c.description;
        facts.systemc = c.systemc;
        facts.version = options["--version"];
        facts.libdir = options["--libdir"];
        // The file as the component names it: relative to the source tree.
        VerilogModule m = read_module_header(rtl + "/" + c.top + ".v");
        m.file = std::string("rtl/") + c.top + ".v";
        facts.tops.push_back(m);
        std::vector<std::string> names;  // relative to rtl/ (device/adder8.v)
        for (const std::string& path : file_closure(modules, m.name))
          names.push_back(path.substr(rtl.size() + 1));
        facts.top_files.push_back(names);
        const std::string file = c.systemc ? main_file : folder + c.name + ".xml";
        ok = write(file, ipxact_component(facts)) && ok;
      }
    } catch (const VerilogError& e) {
      std::cerr << "specular_ip_export: error: " << e.what() << "\n";
      return 2;
    }
  }
  if (options.count("--ipxact-resolved")) {
    const std::string rtl = options["--source-dir"] + "/rtl";
    try {
      const std::map<std::string, std::int64_t> settings =
          options.count("--set") ? parse_settings(options["--set"]) : std::map<std::string, std::int64_t>{};
      VerilogModule m = read_module_header(rtl + "/ip/specular_ip_axi.v", settings);
      for (const VerilogParameter& p : m.parameters) {
        std::int64_t minimum = 0, maximum = 0;
        if (p.is_string) continue;
        if (!parameter_range(m.name, p.name, minimum, maximum)) {
          if (p.width <= 0) continue;
          maximum = (std::int64_t{1} << p.width) - 1;  // a sized parameter: [W-1:0]
        }
        if (p.value < minimum || p.value > maximum)
          throw std::invalid_argument("--set: " + p.name + " = " + std::to_string(p.value) +
                                      " is outside " + std::to_string(minimum) + ".." +
                                      std::to_string(maximum));
      }
      m.file = "rtl/ip/specular_ip_axi.v";
      const auto modules = read_modules({rtl + "/device", rtl + "/primitives", rtl + "/design_space",
                                         rtl + "/ip"});
      ComponentFacts facts;
      facts.name = "specular_ip_axi";
      facts.description = std::string(axi_description) +
                          "; resolved: numbers at the parameters' values below, for tools that "
                          "evaluate no expression (specular_ip_axi.xml has the expressions)";
      facts.systemc = false;
      facts.version = options["--version"];
      facts.libdir = options["--libdir"];
      facts.resolved = true;
      facts.tops.push_back(m);
      std::vector<std::string> names;
      for (const std::string& path : file_closure(modules, m.name)) names.push_back(path.substr(rtl.size() + 1));
      facts.top_files.push_back(names);
      ok = write(options["--ipxact-resolved"], ipxact_component(facts)) && ok;
    } catch (const VerilogError& e) {
      std::cerr << "specular_ip_export: error: " << e.what() << "\n";
      return 2;
    } catch (const std::invalid_argument& e) {
      std::cerr << "specular_ip_export: error: " << e.what() << "\n";
      return 2;
    }
  }
  return ok ? 0 : 2;
}

}  // namespace

int main(int argc, char** argv) {
  specular::cli::Command app{"The IP's descriptions for SoC tools, written from the register map and the Verilog tops'\n"
                             "headers (docs/ipxact.md). FILE \"-\" is standard output.",
                             "specular_ip_export"};
  specular::cli::house_rules(app, "Exit status: 0 written, 2 bad arguments, an unreadable Verilog file or an "
                                  "unwritable output.");
  app.disable_version_flag();  // --version V is the component's version here
  std::map<std::string, std::string> options{{"--version", SPECULAR_PACKAGE_VERSION}, {"--libdir", "lib"}};
  const auto option = [&](const std::string& name, const std::string& type, const std::string& help) {
    return app
        .add_option_function<std::string>(
            name, [&options, name](const std::string& v) { options[name] = v; }, help)
        ->type_name(type);
  };
  option("--ipxact", "FILE",
         "the IEEE 1685-2014 components, one per Verilog top: FILE (the SystemC targets with the drawn "
         "device, ip/specular_unit.xml) and beside it specular_device_sync.xml and specular_ip_axi.xml");
  option("--systemrdl", "FILE", "the SystemRDL 2.0 addrmap (ip/specular_unit.rdl)");
  option("--json", "FILE", "the C++ map as plain JSON, for the tests (no writer's code)");
  option("--verilog", "FILE", "the register block in Verilog (rtl/ip/specular_reg_block.v)");
  option("--bus-dir", "DIR",
         "the bus and abstraction definitions of the socket's bus type "
         "(ip/tlm2_generic_payload.busdef.xml, .absdef.xml)");
  option("--ipxact-resolved", "FILE",
         "specular_ip_axi's component with numbers where specular_ip_axi.xml has expressions of its "
         "parameters, at their defaults or at --set's values: for tools that evaluate no IP-XACT "
         "expression (PeakRDL-ipxact's importer; docs/ipxact.md)");
  option("--set", "N=V[,N=V]",
         "specular_ip_axi's integer parameters for --ipxact-resolved (CONFIG_VALUE=0x080D1051,ADDR_WIDTH=16)")
      ->check(specular::cli::parsed_by(parse_settings));
  option("--source-dir", "DIR", "the source tree: rtl/device/ holds the Verilog tops");
  option("--version", "V", "the component's version (default: the package's, " SPECULAR_PACKAGE_VERSION ")");
  option("--libdir", "D", "the install's library folder, relative to the prefix (default lib)");
  return specular::cli::run(app, argc, argv, [&] { return export_ip(options); });
}
