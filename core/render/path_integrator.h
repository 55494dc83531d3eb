// Unidirectional path tracing: from each camera ray, one path that bounces by sampling the BSDF
// (materials/bsdf.h), with next-event estimation at every smooth bounce (a shadow ray to each
// light and one to a point of the emissive surfaces) and multiple importance sampling (Veach's
// power heuristic) wherever both strategies can find the same light: rect lights, emissive mesh
// triangles, an environment image. Point, spot and directional lights are reached by light
// sampling alone, a uniform background colour by BSDF sampling alone. Russian roulette ends paths whose
// throughput is low after kRouletteStart bounces, by Cycles' rule. docs/rendering.md, "Path tracing".
#pragma once

#include "core/render/integrator.h"
#include "materials/bsdf.h"

namespace rt {

class PathIntegrator final : public Integrator {
 public:
  Vec3 radiance_from_hit(const Ray& ray, const SceneHit& met, int depth, TraceContext& ctx) const override;

  // Bounces always taken before roulette may end a path: Cycles' min_light_bounces + 1 (the twins in
  // tools/cycles set it to 3, to match). Measured (docs/benchmark.md): from the third bounce,
  // surviving by the throughput itself, the Cornell box left 1.26 times the squared error at equal
  // time, the Blender fixture 1.23 times.
  static constexpr int kRouletteStart = 4;
  // Point, spot and directional lights deliver pi x colour (x attenuation): a white Lambert
  // surface facing a light of colour c then reflects c, as under Whitted's Phong rule.
  static constexpr float kDeltaLightScale = kPi;

  // Light reaching the surface from every light and the emissive surfaces, each one sample with
  // a shadow ray, times the BSDF (MIS-weighted against BSDF sampling where it applies).
  Vec3 direct_light(const EvaluatedSurface& s, const Bsdf& bsdf, int bounce, TraceContext& ctx) const;
};

}  // namespace rt
