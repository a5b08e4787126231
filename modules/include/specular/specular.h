// The one public header: everything a user of the IP needs.
#pragma once

#include "specular/arith.h"
#include "specular/core.h"
#include "specular/device.h"
#include "specular/format.h"
#include "specular/pin_harness.h"
#include "specular/reference.h"
