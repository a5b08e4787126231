/// \file
/// The one public header: everything a user of the IP needs.
#pragma once

#include "specular/arith.h"
#include "specular/core.h"
#include "specular/device.h"
#include "specular/format.h"
#include "specular/pin_harness.h"
#include "specular/reference.h"
#include "specular/tlm/driver.h"
#include "specular/tlm/energy_counter.h"
#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "specular/tlm/register_map.h"
#include "specular/tlm/target.h"

/// \namespace specular
/// The specular colour intensity IP of UA 59965 U: the bit-accurate Core, the pin-level
/// SystemC device and its harness, the TLM-2.0 targets, register map and driver, and
/// (SpecularUnit::twin) the RTL twin. See the reference's front page for where to start.

/// \namespace specular::energy
/// The energy model (issue 61, docs/energy.md): an operation's energy from its toggles,
/// fitted to gate-level replays (operation_features.h, calibration.h), and the meter the
/// TLM targets price their work with (energy_meter.h).
