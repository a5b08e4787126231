// The C++ register map as plain JSON, for the tests that read the IP-XACT and SystemRDL
// files back (tests/ipxact/): a dump of register_map and register_fields as they are (offsets,
// words, access, the reset of every word, fields, enumerations), through none of the
// writers' code, so that a test compares the files with the C++ table itself.
#pragma once

#include <string>

namespace specular {
namespace ip_export {

std::string register_map_json();

}  // namespace ip_export
}  // namespace specular
