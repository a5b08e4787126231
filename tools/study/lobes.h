// The specular lobes the study compares with the exact cos^n λ.
//
// The exact lobe and the patent's formula in double come from reference.h, and the
// device's values from Core (one truth per block). What lives here are the two
// published alternatives the device competes with, and the table of the device's
// values for every cos code, read from Core.
#pragma once

#include <string>
#include <vector>

#include "specular/core.h"

namespace specular {
namespace study {

/// Schlick's rational approximation of cos^n (Schlick 1994): t / (n − n·t + t).
double schlick(double t, unsigned n);

/// The approximation of US 5739820 (the seed's "known device", Fig. 7C/7D there):
/// max(0, 1 − n·(1 − t)/4)^4, i.e. (1 − x/4)^4 ≈ e^−x with x = n·(1 − t).
double us5739820(double t, unsigned n);

/// Where the patent's formula 1 − ½·log2(1 − n·log2 t) is zero: n·log2 t = −3, so
/// t = 2^(−3/n). Below it the unclamped formula is negative.
double formula_zero_crossing(unsigned n);

/// What the study reads from the device for one cos code.
enum class DeviceValue {
  approx,      ///< register 9 after pass 2: A ≈ cos^n λ
  normalised,  ///< multiplier 39: K(n)·A, with K(n) from ROM 38
};

/// The device's value at every cos code 0 .. 2^F for one n, as reals, computed by
/// `core` (RGB registers are irrelevant here). Index = cos code.
std::vector<double> device_table(const Core& core, unsigned n, DeviceValue value);

/// The real value of cos code `code` (code · 2^−F).
double cos_of_code(const Core& core, code_t code);

/// A short, file-name-safe label for a device configuration: "device_clamp",
/// "device_literal" …
std::string device_label(Saturation saturation);

}  // namespace study
}  // namespace specular
