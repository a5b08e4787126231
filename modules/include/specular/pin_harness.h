/// \file
/// The harness around the pin-level SystemC device: DeviceHarness (device_harness.h)
/// driving SpecularDevice, the netlist of Fig. 1 and Fig. 2.
#pragma once

#include "specular/device.h"
#include "specular/device_harness.h"

namespace specular {

/// The harness of the pin-level SystemC device: the `pin` model of specular_tb.
using PinHarness = DeviceHarness<SpecularDevice>;
extern template class DeviceHarness<SpecularDevice>;  // instantiated in pin_harness.cpp

}  // namespace specular
