// The patent's energy claim, measured: the hemisphere integral (equation 6) of every
// lobe under every normalisation policy, for every n — the data of Fig. 5 and Fig. 6.
#pragma once

#include <array>
#include <vector>

#include "specular/core.h"
#include "study_options.h"

namespace specular {
namespace study {

/// Unnormalised integrals (K = 1) of the lobes that do not depend on the policy, for one n.
struct LobeIntegrals {
  double exact_closed_form = 0;  ///< 2π/(n+2)
  double exact = 0;              ///< cos^n by quadrature (checks the quadrature)
  double formula_clamp = 0;
  double formula_literal = 0;
  double schlick = 0;
  double us5739820 = 0;
};
LobeIntegrals lobe_integrals(unsigned n, int cos_frac_bits);

/// The device's integral: its K(n)·A (multiplier 39) for every cos code, from `core`,
/// integrated exactly over the codes' rounding intervals.
double device_integral(const Core& core, unsigned n);

/// One row of energy_integrals.csv.
struct EnergyRow {
  unsigned n = 0;
  Normalisation policy = Normalisation::patent;
  double k = 0;                  ///< K(n) of the policy (exact, not ROM 38's rounded word)
  LobeIntegrals scaled;          ///< lobe_integrals(n) × K(n)
  double device_clamp = 0;       ///< the device, saturating (default)
  double device_literal = 0;     ///< the device, keeping negative results
};

/// Writes energy_integrals.csv (one row per n and policy) into options.out_dir and
/// returns the rows.
std::vector<EnergyRow> run_energy_study(const StudyOptions& options);

/// One row of energy_device_energy.csv: normalisation device-energy (issue 14) and,
/// beside it, `energy`, under one constants policy, for one n.
struct DeviceEnergyRow {
  unsigned n = 0;
  Constants constants = Constants::patent;
  double rom38_word = 0;     ///< ROM 38's word 1/I(n) under device-energy, as a real
  double device_energy = 0;  ///< equation-6 integral of multiplier 39 under device-energy
  double energy = 0;         ///< the same under `energy`, s·(n+2)/(2π)
};

/// Writes energy_device_energy.csv (every n × the three constants policies; the
/// device clamps) and returns the rows.
std::vector<DeviceEnergyRow> run_device_energy_study(const StudyOptions& options);

}  // namespace study
}  // namespace specular
