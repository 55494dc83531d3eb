// Direct light: the proposal's ambient term plus, for every light, Phong diffuse and specular
// times the light's visibility along a shadow ray (shadow_transmittance: opaque blockers shadow
// fully, glass partly).
#pragma once

#include "core/render/integrator.h"
#include "materials/evaluated_surface.h"

namespace rt {

Vec3 direct_lighting(const EvaluatedSurface& s, TraceContext& ctx);

}  // namespace rt
