// Direct light: the proposal's ambient term plus, for every light, Phong diffuse and specular
// times the light's visibility along a shadow ray (shadow_transmittance: opaque blockers shadow
// fully, glass partly). Area lights average render.shadow_samples stratified samples: soft shadows.
#pragma once

#include "core/render/integrator.h"
#include "materials/evaluated_surface.h"

namespace rt {

// What the shadow rays from one point towards the point, spot and directional lights found, when
// asked beforehand for a packet of neighbouring points (find_point_shadows): bit l for light l.
struct PointShadows {
  static constexpr size_t kMaxLights = 8;  // lights after these trace their rays as they are shaded
  uint32_t known = 0;                      // light l's answer is here
  uint32_t lit = 0;                        // and light l reaches the point: it has a shadow ray, and nothing blocks it
  // Where lit: the light's sample at the point (its direction and radiance), not drawn again.
  Vec3 direction[kMaxLights];
  Vec3 radiance[kMaxLights];
};

// `path` keys the area-light samples (core/sampling.h); `weight` is the hit's weight in its pixel
// (1 for a camera ray's hit), which scales an area light's samples at secondary hits
// (render.secondary_shadows, core/render_settings.h). `known`: the point lights' answers found
// beforehand, if any; the others' shadow rays are traced here.
Vec3 direct_lighting(const EvaluatedSurface& s, uint64_t path, float weight, TraceContext& ctx,
                     const PointShadows* known = nullptr);

// For count <= kPacketSize points (`has[i]`: point i is there, the others are skipped): their
// shadow rays towards each point, spot and directional light, traced as one packet
// (Bvh::occluded_packet) and counted as direct_lighting counts them, so that it need not trace
// them one by one. Neighbouring camera rays' hits make coherent packets. A packet finds the
// answer each ray would alone, so the image is the same. In a scene with glass, a ray the packet
// finds blocked is left unknown, for direct_lighting to trace through the glass
// (shadow_transmittance); one that meets nothing is lit there too.
void find_point_shadows(const EvaluatedSurface* s, const bool* has, int count, const Scene& scene,
                        RayCounters& counters, PointShadows* out);

// Where a shadow ray from the surface towards `direction` starts: off the surface by its rounding
// bound, from the lifted point on a smooth mesh (Hanika; SurfaceInteraction::shadow_lift).
Vec3 shadow_ray_origin(const EvaluatedSurface& s, Vec3 direction);

}  // namespace rt
