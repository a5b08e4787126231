#include "specular/energy/energy_meter.h"

#include "specular/core.h"

namespace specular::energy {

EnergyMeter::EnergyMeter(Calibration calibration, const Formats& formats)
    : calibration_(calibration), features_(formats) {}
EnergyMeter::~EnergyMeter() = default;
EnergyMeter::EnergyMeter(EnergyMeter&&) noexcept = default;
EnergyMeter& EnergyMeter::operator=(EnergyMeter&&) noexcept = default;

void EnergyMeter::operation(const Config& config, const Operands& in) {
  if (!core_) core_ = std::make_unique<Core>(config);
  operation(in, core_->run(in));
}

EnergyTally EnergyMeter::tally(double clocks) const {
  const CalibrationTable& t = table(calibration_);
  EnergyTally out;
  out.operations = operations_;
  out.reads = reads_;
  out.writes = writes_;
  out.clocks = clocks;
  for (std::size_t i = 0; i < feature_count; ++i) out.operation_pj += t.pj_per_feature[i] * sums_[i];
  out.read_pj = bus_table.read_pj * static_cast<double>(reads_);
  out.write_pj = bus_table.write_pj * static_cast<double>(writes_);
  out.clock_pj = bus_table.idle_clock_pj * clocks;
  return out;
}

}  // namespace specular::energy
