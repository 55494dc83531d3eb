// Shadow rays through glass.
#pragma once

#include "core/scene.h"

namespace rt {

// The fraction of light that passes along a shadow ray, per channel: 0 when anything opaque is
// in the way; otherwise, for every transmissive surface crossed, its transmission times the
// Fresnel transmittance 1 - F (Schlick, against air), times Beer-Lambert absorption over the
// distance inside each absorbing object. So glass casts a lighter, tinted shadow, darker at
// the rim. Shadow rays are not bent (no caustics). Any-hit traversal with a visitor: it stops
// at the first opaque surface.
Vec3 shadow_transmittance(const Scene& scene, const Ray& ray);

}  // namespace rt
