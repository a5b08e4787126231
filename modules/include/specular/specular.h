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
#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "specular/tlm/register_map.h"
#include "specular/tlm/target.h"
