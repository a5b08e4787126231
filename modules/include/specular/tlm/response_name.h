/// \file
/// The name of a TLM-2.0 response status, for the messages of a refused access.
#pragma once

#include <tlm>

namespace specular {

/// The enumerator's own name ("TLM_ADDRESS_ERROR_RESPONSE", ...), as IEEE 1666 spells it.
/// tlm_generic_payload::get_response_string() names only the payload's current status,
/// and both the target's refusal report and SpecularDriver's error name a status that is
/// no longer (or not yet) the payload's.
const char* response_name(tlm::tlm_response_status status);

}  // namespace specular
