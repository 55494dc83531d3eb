// KHR_materials_iridescence's Fresnel term: a thin dielectric film over the base, the
// interference of the light reflected at its two faces (Belcour and Barla, "A Practical Extension
// to Microfacet Theory for the Modeling of Varying Iridescence", 2017), as the glTF specification
// and the Khronos sample viewer evaluate it: Airy summation of the first orders with the
// spectral integration done analytically (Gaussian fits of the CIE matching functions in Fourier
// space), then XYZ to linear Rec.709.
#pragma once

#include "core/math.h"

namespace rt {

// The film's reflectance for light at cosine `cos_theta` (with the microfacet normal) in a
// medium of index `outside_ior`, through a film of index `film_ior` and `thickness_nm`, over a
// base whose reflectance head-on is `base_f0` (a metal's colour, a dielectric's F0). In [0, 1];
// a film of thickness 0 gives back the base's Schlick term.
Vec3 thin_film_fresnel(float outside_ior, float film_ior, float cos_theta, float thickness_nm, Vec3 base_f0);

}  // namespace rt
