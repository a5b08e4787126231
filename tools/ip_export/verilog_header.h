// The interface of a Verilog module as an IP-XACT model needs it: its parameters with
// their default values and its ports with direction and width at those defaults.
// A small reader of the ANSI header `module NAME #(parameter ...) (input wire ... );`
// as rtl/ writes it (lowRISC style: one module per file), and of which modules a
// module instantiates, for the file set of a top. Not a Verilog front end: what it
// reads is checked against Yosys's reading of the same files (tests/ipxact/).
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace specular {
namespace ip_export {

struct VerilogParameter {
  std::string name;
  bool is_string = false;
  std::int64_t value = 0;   ///< the default, evaluated (integers)
  std::string text;         ///< the default as a string literal's contents (strings)
  int width = 0;            ///< 0: unsized; else the bits of its [msb:0] range
};

struct VerilogPort {
  std::string name;
  std::string direction;  ///< "in" or "out" (IP-XACT's words)
  bool is_signed = false;
  int msb = 0, lsb = 0;   ///< at the parameters' defaults; both 0 for a scalar
  std::string msb_expression;  ///< the msb as written when it names a parameter (ADDR_WIDTH - 1)
  bool is_vector = false;
};

struct VerilogModule {
  std::string name;
  std::string file;  ///< the file it was read from, as given
  std::vector<VerilogParameter> parameters;
  std::vector<VerilogPort> ports;
  std::set<std::string> instantiates;  ///< names of other known modules in its body
};

struct VerilogError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads the first module of `path`. Throws VerilogError naming the file, the line
/// and what was expected. `overrides`: integer parameters set to other values than their
/// defaults (as an instantiation would), which the ports' widths then follow; a name the
/// module has no integer parameter of is refused (VerilogError).
VerilogModule read_module_header(const std::string& path,
                                 const std::map<std::string, std::int64_t>& overrides = {});

/// Every module of the `.v` files in the folders `dirs`, by name (for the closure below).
std::map<std::string, VerilogModule> read_modules(const std::vector<std::string>& dirs);

/// The files of `top` and of every module it instantiates, directly or not, sorted.
std::vector<std::string> file_closure(const std::map<std::string, VerilogModule>& modules,
                                      const std::string& top);

}  // namespace ip_export
}  // namespace specular
