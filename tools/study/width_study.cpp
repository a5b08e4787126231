#include "width_study.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>

#include "csv.h"
#include "lobes.h"
#include "parallel.h"
#include "specular/core.h"
#include "specular/reference.h"

namespace specular {
namespace study {

namespace {

WidthCase make_case(const char* sweep, int addr, int word, int reg9_frac, int rom38_frac) {
  WidthCase c{sweep, Widths{}};
  c.widths.rom5_addr_bits = addr;
  c.widths.rom5_word_bits = word;
  c.widths.reg9_frac_bits = reg9_frac;
  c.widths.rom38_frac_bits = rom38_frac;
  return c;
}

// Per worker, per case: the worst errors seen so far.
struct Accumulator {
  double vs_formula = 0;
  unsigned worst_n = 0;
  double worst_cos = 0;
  double vs_exact = 0;
  double norm = 0;
};

}  // namespace

std::vector<WidthCase> width_cases(bool quick) {
  const Widths d;
  std::vector<WidthCase> cases;
  if (quick) {
    for (int addr : {13, 15}) cases.push_back(make_case("rom5_addr", addr, d.rom5_word_bits, d.reg9_frac_bits, d.rom38_frac_bits));
    cases.push_back(make_case("rom5_word", d.rom5_addr_bits, 16, d.reg9_frac_bits, d.rom38_frac_bits));
    cases.push_back(make_case("reg9_frac", d.rom5_addr_bits, d.rom5_word_bits, 18, d.rom38_frac_bits));
    cases.push_back(make_case("rom38_frac", d.rom5_addr_bits, d.rom5_word_bits, d.reg9_frac_bits, 10));
    return cases;
  }
  for (int addr = 8; addr <= 22; ++addr)
    cases.push_back(make_case("rom5_addr", addr, d.rom5_word_bits, d.reg9_frac_bits, d.rom38_frac_bits));
  for (int word = 10; word <= 30; ++word)
    cases.push_back(make_case("rom5_word", d.rom5_addr_bits, word, d.reg9_frac_bits, d.rom38_frac_bits));
  for (int frac = d.cos_frac_bits; frac <= 32; ++frac)
    cases.push_back(make_case("reg9_frac", d.rom5_addr_bits, d.rom5_word_bits, frac, d.rom38_frac_bits));
  for (int frac = 6; frac <= 24; ++frac)
    cases.push_back(make_case("rom38_frac", d.rom5_addr_bits, d.rom5_word_bits, d.reg9_frac_bits, frac));
  for (int addr = 10; addr <= 20; ++addr)
    for (int word = 14; word <= 26; word += 2)
      cases.push_back(make_case("grid", addr, word, d.reg9_frac_bits, d.rom38_frac_bits));
  return cases;
}

std::vector<WidthResult> explore_widths(const std::vector<WidthCase>& cases,
                                        const std::vector<unsigned>& ns, unsigned workers,
                                        bool quiet) {
  // The grid repeats some cases of the one-at-a-time sweeps: measure each distinct
  // device once (unique_of[i] = its index in `cores`).
  std::vector<std::unique_ptr<Core>> cores;
  std::vector<std::size_t> unique_of(cases.size());
  std::map<std::array<int, 4>, std::size_t> seen;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Widths& w = cases[i].widths;
    const std::array<int, 4> key = {w.rom5_addr_bits, w.rom5_word_bits, w.reg9_frac_bits,
                                    w.rom38_frac_bits};
    const auto [it, inserted] = seen.emplace(key, cores.size());
    if (inserted)
      cores.push_back(std::make_unique<Core>(Config{w, Normalisation::patent, Saturation::clamp}));
    unique_of[i] = it->second;
  }
  const Formats reference_formats;  // every case keeps the default cos format (U1.16)
  const code_t one = reference_formats.cos.one();
  const int bits = reference_formats.cos.frac_bits;
  for (const WidthCase& c : cases)
    if (c.widths.cos_frac_bits != bits)
      throw std::invalid_argument("explore_widths: every case must keep cos_frac_bits = " +
                                  std::to_string(bits));

  std::vector<std::vector<Accumulator>> acc(std::max(1u, workers),
                                            std::vector<Accumulator>(cores.size()));
  parallel_for("width exploration (" + std::to_string(cores.size()) + " devices)", ns.size(),
               workers, quiet, [&](std::size_t item, unsigned worker) {
    const unsigned n = ns[item];
    std::vector<double> formula(static_cast<std::size_t>(one) + 1), exact(formula.size());
    for (code_t c = 0; c <= one; ++c) {
      const double cos = reference_formats.cos.to_real(c);
      formula[static_cast<std::size_t>(c)] = reference::approx(cos, n, Saturation::clamp, bits);
      exact[static_cast<std::size_t>(c)] = reference::exact_lobe(cos, n);
    }
    const double k = reference::k(n, Normalisation::patent);
    const double norm_scale = 1.0 / std::max(1.0, k);
    for (std::size_t i = 0; i < cores.size(); ++i) {
      const Core& core = *cores[i];
      const Formats& f = core.formats();
      Accumulator& a = acc[worker][i];
      Operands in;
      in.n = n;
      for (code_t c = 0; c <= one; ++c) {
        in.cos = c;
        const Result r = core.run(in);
        const double device = f.reg9.to_real(r.reg9_pass2);
        const double ref = formula[static_cast<std::size_t>(c)];
        const double e = std::abs(device - ref);
        if (e > a.vs_formula) a = {e, n, reference_formats.cos.to_real(c), a.vs_exact, a.norm};
        a.vs_exact = std::max(a.vs_exact, std::abs(device - exact[static_cast<std::size_t>(c)]));
        a.norm = std::max(a.norm, std::abs(f.norm.to_real(r.norm39) - k * ref) * norm_scale);
      }
    }
  });

  std::vector<WidthResult> results;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    WidthResult r;
    r.config = cases[i];
    const std::size_t u = unique_of[i];
    r.rom5_bits = cores[u]->formats().rom5_bits();
    r.rom38_bits = cores[u]->formats().rom38_bits();
    for (const auto& per_worker : acc) {
      const Accumulator& a = per_worker[u];
      if (a.vs_formula > r.max_err_vs_formula) {
        r.max_err_vs_formula = a.vs_formula;
        r.worst_n = a.worst_n;
        r.worst_cos = a.worst_cos;
      }
      r.max_err_vs_exact = std::max(r.max_err_vs_exact, a.vs_exact);
      r.max_norm_err = std::max(r.max_norm_err, a.norm);
    }
    results.push_back(r);
  }
  return results;
}

std::vector<WidthResult> run_width_study(const StudyOptions& options) {
  const std::vector<WidthResult> results =
      explore_widths(width_cases(options.quick), options.n_values(), options.workers,
                     options.quiet);
  const Widths d;
  {
    CsvWriter csv(options.out_dir + "/widths.csv",
                  {"sweep", "rom5_addr_bits", "rom5_word_bits", "reg9_frac_bits",
                   "rom38_frac_bits", "is_default", "rom5_words", "rom5_bits", "rom38_bits",
                   "max_err_vs_formula", "worst_n", "worst_cos", "max_err_vs_exact",
                   "max_norm_err"});
    for (const WidthResult& r : results) {
      const Widths& w = r.config.widths;
      const bool is_default = w.rom5_addr_bits == d.rom5_addr_bits &&
                              w.rom5_word_bits == d.rom5_word_bits &&
                              w.reg9_frac_bits == d.reg9_frac_bits &&
                              w.rom38_frac_bits == d.rom38_frac_bits;
      csv.cell(r.config.sweep).cell(static_cast<long long>(w.rom5_addr_bits));
      csv.cell(static_cast<long long>(w.rom5_word_bits)).cell(static_cast<long long>(w.reg9_frac_bits));
      csv.cell(static_cast<long long>(w.rom38_frac_bits)).cell(static_cast<long long>(is_default));
      csv.cell(static_cast<long long>(1) << w.rom5_addr_bits).cell(static_cast<long long>(r.rom5_bits));
      csv.cell(static_cast<long long>(r.rom38_bits)).cell(r.max_err_vs_formula);
      csv.cell(static_cast<long long>(r.worst_n)).cell(r.worst_cos).cell(r.max_err_vs_exact);
      csv.cell(r.max_norm_err);
      csv.end_row();
    }
  }

  // Near cos = 1, with fewer than cos_frac_bits − 1 address bits ROM 5 drops low bits of
  // the cos code: neighbouring codes read the same word and n·log2 cos is off by up to
  // n·2^−addr/ln 2 (n = 1000 magnifies it most).
  {
    CsvWriter csv(options.out_dir + "/widths_near_one.csv",
                  {"rom5_addr_bits", "n", "cos_code", "cos", "device", "formula", "exact"});
    const unsigned n = n_max;
    const int bits = d.cos_frac_bits;
    for (int addr = bits - 4; addr <= bits; ++addr) {
      Widths w;
      w.rom5_addr_bits = addr;
      const Core core(Config{w, Normalisation::none, Saturation::clamp});
      const Formats& f = core.formats();
      Operands in;
      in.n = n;
      for (code_t c = f.cos.one() - 160; c <= f.cos.one(); ++c) {
        in.cos = c;
        const double cos = f.cos.to_real(c);
        csv.cell(static_cast<long long>(addr)).cell(static_cast<long long>(n));
        csv.cell(static_cast<long long>(c)).cell(cos);
        csv.cell(f.reg9.to_real(core.run(in).reg9_pass2));
        csv.cell(reference::approx(cos, n, Saturation::clamp, bits));
        csv.cell(reference::exact_lobe(cos, n));
        csv.end_row();
      }
    }
  }
  return results;
}

}  // namespace study
}  // namespace specular
