// The SystemRDL 2.0 description of the register map (register_map.h, register_fields.h):
// one addrmap, a reg per register, its fields with sw/hw access, onwrite = woclr,
// singlepulse, resets and enums; OPERANDS and RESULTS as regfiles of the registers
// they alias, BATCH_COS and BATCH_OUT as register arrays. ip/specular_unit.rdl is its
// output; docs/ipxact.md says how it maps the C++ table.
#pragma once

#include <string>

namespace specular {
namespace ip_export {

std::string systemrdl_addrmap(const std::string& version);

}  // namespace ip_export
}  // namespace specular
