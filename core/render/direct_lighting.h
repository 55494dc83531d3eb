// Direct light: the proposal's ambient term plus, for every light, Phong diffuse and specular
// times the light's visibility along a shadow ray (shadow_transmittance: opaque blockers shadow
// fully, glass partly). Area lights average render.shadow_samples stratified samples: soft shadows.
#pragma once

#include "core/render/integrator.h"
#include "materials/evaluated_surface.h"

namespace rt {

// `path` keys the area-light samples (core/sampling.h); `weight` is the hit's weight in its pixel
// (1 for a camera ray's hit), which scales an area light's samples at secondary hits
// (render.secondary_shadows, core/render_settings.h).
Vec3 direct_lighting(const EvaluatedSurface& s, uint64_t path, float weight, TraceContext& ctx);

// Where a shadow ray from the surface towards `direction` starts: off the surface by its rounding
// bound, from the lifted point on a smooth mesh (Hanika; SurfaceInteraction::shadow_lift).
Vec3 shadow_ray_origin(const EvaluatedSurface& s, Vec3 direction);

}  // namespace rt
