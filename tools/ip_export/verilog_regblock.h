// The register file of the IP in Verilog-2005 (rtl/ip/specular_reg_block.v), written from
// the register map and its fields: decode, storage, resets, W1C, START as a pulse, the
// range checks, STATUS.ERROR with CAUSE and ERROR_ADDRESS, holes. The bus adapter
// (rtl/ip/specular_ip_axi.v) and the device around it are written by hand.
#pragma once

#include <string>

namespace specular {
namespace ip_export {

/// The file's name under rtl/ip/ and the module it holds.
inline constexpr const char* register_block_module = "specular_reg_block";

/// The whole Verilog file.
std::string verilog_register_block();

}  // namespace ip_export
}  // namespace specular
