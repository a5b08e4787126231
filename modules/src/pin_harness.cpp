#include "specular/pin_harness.h"

namespace specular {

template class DeviceHarness<SpecularDevice>;

}  // namespace specular
