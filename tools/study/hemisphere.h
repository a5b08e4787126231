// The patent's equation 6: the hemisphere integral of a lobe,
//   2π ∫_0^{π/2} f(cos θ) cos θ sin θ dθ  =  2π ∫_0^1 f(t) t dt   (t = cos θ).
// It is 1 for a lobe that reflects exactly the light it receives (Fig. 5, Fig. 6).
#pragma once

#include <functional>
#include <vector>

namespace specular {
namespace study {

/// 2π ∫_0^1 f(t)·t dt by adaptive Gauss–Kronrod (7/15) quadrature. `breaks` are the
/// points in (0, 1) where f has a kink (the clamp at the formula's zero crossing, the
/// log2-0 floor, the end of US 5739820's support); integrating piece by piece keeps
/// the quadrature at full accuracy. Absolute error ≲ `tolerance`.
double hemisphere_integral(const std::function<double(double)>& f, std::vector<double> breaks,
                           double tolerance = 1e-13);

/// The same integral, exactly, for a lobe that is constant on each cos code's
/// rounding interval, as the device's is: register 1 holds round(t·2^F), so
/// f(t) = values[c] for t ∈ [(c − ½)·2^−F, (c + ½)·2^−F) ∩ [0, 1], and the integral is
/// Σ_c values[c] · π·(b_c² − a_c²). `values` has one entry per code 0 .. 2^F.
double hemisphere_integral_of_codes(const std::vector<double>& values, int cos_frac_bits);

}  // namespace study
}  // namespace specular
