// KHR_materials_dispersion in the path tracer: a path that meets dispersive glass carries one
// wavelength from then on (a "hero" wavelength, drawn uniformly in 380-780 nm), refracted at that
// wavelength's index, and its RGB throughput weighted by the wavelength's colour. Averaged over
// the wavelengths the weights are (1, 1, 1), so white light stays white and splits into its
// spectrum where the index varies.
#pragma once

#include "core/math.h"

namespace rt {

inline constexpr float kShortestWavelength = 380.0f, kLongestWavelength = 780.0f;  // nanometres

// The index at `wavelength_nm` of a glass of index `ior` (at the d line, 587.56 nm) and glTF's
// `dispersion` (20 / the Abbe number): Cauchy's n = A + B / lambda^2 through the specification's
// ior + (ior - 1) / V (523655 / lambda^2 - 1.5168); at least 1.
float dispersed_ior(float ior, float dispersion, float wavelength_nm);

// u in [0, 1) to a wavelength (uniform density).
inline float wavelength_from(float u) { return kShortestWavelength + (kLongestWavelength - kShortestWavelength) * u; }

// The RGB weight of a path at `wavelength_nm` drawn uniformly: the CIE 1931 matching functions
// (Wyman, Sloan and Shirley's fit, 2013) in linear Rec.709, negatives cut, each channel scaled so
// that its mean over the range is 1.
Vec3 wavelength_weight(float wavelength_nm);

}  // namespace rt
