/// \file
/// Double-precision references: the patent's formula on the quantised inputs, and
/// the exact Blinn–Phong lobe. Independent of the fixed-point arithmetic: nothing
/// here reads a format other than the resolution of the cos λ input.
#pragma once

#include <array>

#include "specular/format.h"

namespace specular {
/// Double-precision references of the patent's formula and the exact lobe (see reference.h).
namespace reference {

/// log2 cos λ, with log2 0 defined as log2 of the smallest non-zero code, −F
/// (spec, Decision "log2 0").
double log2_cos(double cos_q, int cos_frac_bits);

/// A = a − h·log2(a − n·log2 cos λ) with the policy's constants on pins 20 and 19
/// (the patent's: 1 − ½·log2(1 − n·log2 cos λ)), saturated at 0 under Saturation::clamp.
double approx(double cos_q, unsigned n, Saturation saturation, int cos_frac_bits,
              Constants constants = Constants::patent);

/// ROM 38's K(n), scaled by the constants' s: s·2π/(n+2), s·(n+2)/(2π), s, or under
/// `device_energy` 1/I(n), I(n) = Σ_codes approx(clamp)·code_interval_integral: the
/// double formula's own equation-6 integral (the device's is within ~1e-5 of it).
double k(unsigned n, Normalisation policy, Constants constants = Constants::patent,
         int cos_frac_bits = 16);

/// 2π ∫ t dt over cos code c's rounding interval [(c − ½)·2^−F, (c + ½)·2^−F] ∩ [0, 1]:
/// the weight of a lobe that is constant on each code in the equation-6 integral.
double code_interval_integral(long long code, int cos_frac_bits);

/// The exact lobe cos^n λ.
double exact_lobe(double cos_q, unsigned n);

/// Every reference figure for one computation, as the testbench reports them.
struct Figures {
  double cos_q = 0;              ///< the value held in register 1
  double approx_ref = 0;         ///< A in double, same saturation policy
  double norm_ref = 0;           ///< K(n)·approx_ref
  double norm_exact = 0;         ///< K(n)·cos_q^n
  std::array<double, 3> out_ref{};  ///< norm_ref·R, ·G, ·B
};

/// Every Figures value for one computation: cos_q the cos λ register 1 holds (already
/// quantised), rgb the intensities (0..255), the policies and constants as the device's.
Figures evaluate(double cos_q, unsigned n, const std::array<double, 3>& rgb,
                 Normalisation normalisation, Saturation saturation, int cos_frac_bits,
                 Constants constants = Constants::patent);

/// Accuracy bounds the device is held to (issue 2, item 7).
double approx_tolerance();                        ///< 2^-10
double norm_tolerance(double k);                  ///< 2^-10·max(1, K)
double out_tolerance(double k, double intensity, double out_lsb);  ///< 2^-10·max(1,K)·I + 1 LSB

}  // namespace reference
}  // namespace specular
