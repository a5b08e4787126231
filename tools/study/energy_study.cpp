#include "energy_study.h"

#include <cmath>

#include "csv.h"
#include "hemisphere.h"
#include "lobes.h"
#include "parallel.h"
#include "specular/reference.h"

namespace specular {
namespace study {

namespace {
constexpr double two_pi = 6.283185307179586476925286766559;
constexpr std::array<Normalisation, 3> policies = {Normalisation::none, Normalisation::patent,
                                                   Normalisation::energy};
constexpr std::array<Saturation, 2> saturations = {Saturation::clamp, Saturation::literal};
}  // namespace

LobeIntegrals lobe_integrals(unsigned n, int cos_frac_bits) {
  // Kinks: the formula's zero crossing (clamp), the log2-0 floor at the smallest
  // cos code, and the end of US 5739820's support (t = 1 − 4/n).
  const double zero = formula_zero_crossing(n);
  const double floor = std::ldexp(1.0, -cos_frac_bits);
  const std::vector<double> kinks = {zero, floor, 1.0 - 4.0 / n};
  LobeIntegrals r;
  r.exact_closed_form = two_pi / (n + 2.0);
  r.exact = hemisphere_integral([n](double t) { return reference::exact_lobe(t, n); }, kinks);
  r.formula_clamp = hemisphere_integral(
      [&](double t) { return reference::approx(t, n, Saturation::clamp, cos_frac_bits); }, kinks);
  r.formula_literal = hemisphere_integral(
      [&](double t) { return reference::approx(t, n, Saturation::literal, cos_frac_bits); }, kinks);
  r.schlick = hemisphere_integral([n](double t) { return schlick(t, n); }, kinks);
  r.us5739820 = hemisphere_integral([n](double t) { return us5739820(t, n); }, kinks);
  return r;
}

double device_integral(const Core& core, unsigned n) {
  return hemisphere_integral_of_codes(device_table(core, n, DeviceValue::normalised),
                                      core.formats().cos.frac_bits);
}

std::vector<EnergyRow> run_energy_study(const StudyOptions& options) {
  // One Core per policy and saturation: the device's K comes from its own ROM 38.
  std::vector<Core> cores;
  for (Normalisation policy : policies)
    for (Saturation saturation : saturations) cores.emplace_back(Config{Widths{}, policy, saturation});
  const int bits = cores.front().formats().cos.frac_bits;

  const std::vector<unsigned> ns = options.n_values();
  std::vector<EnergyRow> rows(ns.size() * policies.size());
  parallel_for("energy integrals (equation 6, every policy)", ns.size(), options.workers,
               options.quiet, [&](std::size_t item, unsigned) {
    const unsigned n = ns[item];
    const LobeIntegrals lobes = lobe_integrals(n, bits);
    for (std::size_t p = 0; p < policies.size(); ++p) {
      EnergyRow& row = rows[item * policies.size() + p];
      row.n = n;
      row.policy = policies[p];
      row.k = reference::k(n, policies[p]);
      row.scaled = {lobes.exact_closed_form * row.k, lobes.exact * row.k,
                    lobes.formula_clamp * row.k,     lobes.formula_literal * row.k,
                    lobes.schlick * row.k,           lobes.us5739820 * row.k};
      row.device_clamp = device_integral(cores[2 * p], n);
      row.device_literal = device_integral(cores[2 * p + 1], n);
    }
  });

  CsvWriter csv(options.out_dir + "/energy_integrals.csv",
                {"n", "policy", "k", "exact_closed_form", "exact", "formula_clamp",
                 "formula_literal", "schlick", "us5739820", "device_clamp", "device_literal"});
  for (const EnergyRow& row : rows) {
    csv.cell(static_cast<long long>(row.n)).cell(std::string(to_string(row.policy))).cell(row.k);
    csv.cell(row.scaled.exact_closed_form).cell(row.scaled.exact).cell(row.scaled.formula_clamp);
    csv.cell(row.scaled.formula_literal).cell(row.scaled.schlick).cell(row.scaled.us5739820);
    csv.cell(row.device_clamp).cell(row.device_literal);
    csv.end_row();
  }
  return rows;
}

std::vector<DeviceEnergyRow> run_device_energy_study(const StudyOptions& options) {
  constexpr std::array<Constants, 3> constants = {Constants::patent, Constants::minimax_half,
                                                  Constants::minimax};
  std::vector<Core> cores;  // per constants: device-energy, energy
  for (Constants c : constants) {
    cores.emplace_back(Config{Widths{}, Normalisation::device_energy, Saturation::clamp, c});
    cores.emplace_back(Config{Widths{}, Normalisation::energy, Saturation::clamp, c});
  }
  const std::vector<unsigned> ns = options.n_values();
  std::vector<DeviceEnergyRow> rows(ns.size() * constants.size());
  parallel_for("device-energy integrals (equation 6, every constants policy)", ns.size(),
               options.workers, options.quiet, [&](std::size_t item, unsigned) {
    for (std::size_t c = 0; c < constants.size(); ++c) {
      DeviceEnergyRow& row = rows[item * constants.size() + c];
      row.n = ns[item];
      row.constants = constants[c];
      const Core& device_energy = cores[2 * c];
      row.rom38_word = device_energy.formats().rom38.to_real(device_energy.rom38().k(row.n));
      row.device_energy = device_integral(device_energy, row.n);
      row.energy = device_integral(cores[2 * c + 1], row.n);
    }
  });
  CsvWriter csv(options.out_dir + "/energy_device_energy.csv",
                {"n", "constants", "rom38_word", "device_energy", "energy"});
  for (const DeviceEnergyRow& row : rows) {
    csv.cell(static_cast<long long>(row.n)).cell(std::string(to_string(row.constants)));
    csv.cell(row.rom38_word).cell(row.device_energy).cell(row.energy);
    csv.end_row();
  }
  return rows;
}

}  // namespace study
}  // namespace specular
