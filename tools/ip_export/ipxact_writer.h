// The IEEE 1685-2014 (IP-XACT) component of the IP, written from the register map
// (register_map.h, register_fields.h) and the Verilog tops' headers (verilog_header.h).
// docs/ipxact.md says what is described and how; ip/specular_unit.xml is its output.
#pragma once

#include <string>
#include <vector>

#include "verilog_header.h"

namespace specular {
namespace ip_export {

/// What a component says beyond the register map. One component per Verilog top, so
/// that every port of a component is its top's and no parameter selects them: the
/// SystemC targets with the drawn device (specular_unit), the synchronous device
/// (specular_device_sync), the whole IP behind AXI4-Lite (specular_ip_axi).
struct ComponentFacts {
  std::string name = "specular_unit";     ///< the VLNV's name, and the file's (NAME.xml)
  std::string description;                ///< the component's description
  bool systemc = true;                    ///< with the SystemC views, their socket and files
  std::string version;                    ///< the package's version (the VLNV's)
  std::string libdir = "lib";             ///< CMAKE_INSTALL_LIBDIR, relative to the prefix
  std::vector<VerilogModule> tops;        ///< its one Verilog top
  std::vector<std::vector<std::string>> top_files;  ///< the top's Verilog files (names only)
  /// specular_ip_axi only: numbers where the component has expressions of its parameters
  /// (resets, the address block's range, AWADDR/ARADDR's width, the module parameters), at
  /// the values its top was read with (read_module_header's overrides): for tools that
  /// evaluate no IP-XACT expression (PeakRDL-ipxact's importer).
  bool resolved = false;
};

/// The values a parameter of a Verilog top may take where the Verilog refuses others
/// (specular_ip_axi's ADDR_WIDTH: 15 to 32); false when it has no such rule.
bool parameter_range(const std::string& top, const std::string& name, std::int64_t& minimum,
                     std::int64_t& maximum);

/// Throws std::invalid_argument unless `facts` has exactly one Verilog top.
std::string ipxact_component(const ComponentFacts& facts);

/// The bus definition and the (TLM) abstraction definition the component's bus
/// interface names: TLM-2.0's generic payload through a 32-bit socket.
std::string ipxact_bus_definition();
std::string ipxact_abstraction_definition();
/// Their file names in ip/ (the component names them by VLNV only).
constexpr const char* bus_definition_file = "tlm2_generic_payload.busdef.xml";
constexpr const char* abstraction_definition_file = "tlm2_generic_payload.absdef.xml";

}  // namespace ip_export
}  // namespace specular
