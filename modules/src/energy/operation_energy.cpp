#include "specular/energy/operation_energy.h"

namespace specular::energy {

const CalibrationTable& table(Calibration calibration) {
  return calibration == Calibration::drawn_device ? drawn_device_table : synchronous_device_table;
}

const char* calibration_name(Calibration calibration) {
  return calibration == Calibration::drawn_device ? "drawn device (specular_device)"
                                                  : "synchronous device (specular_device_sync)";
}

}  // namespace specular::energy
