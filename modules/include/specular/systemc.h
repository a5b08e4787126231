/// \file
/// SystemC include and the one portability shim the modules need.
#pragma once

#include <systemc>

#include "specular/format.h"

// SC_HAS_PROCESS is required by SystemC 2.3 for constructors other than SC_CTOR and
// deprecated from 3.0 (20240329) on, where SC_METHOD/SC_THREAD work without it.
#if SYSTEMC_VERSION < 20240329
/// SC_HAS_PROCESS(module) on SystemC 2.3, nothing on 3.0 and later: put it in a module
/// whose constructor is not SC_CTOR and registers processes.
#define SPECULAR_HAS_PROCESS(module) SC_HAS_PROCESS(module)
#else
#define SPECULAR_HAS_PROCESS(module) static_assert(true, "")
#endif

namespace specular {

/// A data bus carries an integer code; its format is known by the blocks at its ends.
using bus_in = sc_core::sc_in<code_t>;
using bus_out = sc_core::sc_out<code_t>;        ///< a data bus output (an integer code)
using bus_signal = sc_core::sc_signal<code_t>;  ///< a data bus between two blocks
using wire_in = sc_core::sc_in<bool>;           ///< a one-bit control input (pins 27–34, 36, 37)
using wire_out = sc_core::sc_out<bool>;         ///< a one-bit control output
using wire = sc_core::sc_signal<bool>;          ///< a one-bit control signal

}  // namespace specular
