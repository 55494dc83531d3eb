// Whitted ray tracing: direct light at the closest hit, plus mirror reflection, refraction with
// the Fresnel split (Schlick) and the proposal's glossy reflection, traced recursively up to
// render.max_depth bounces. The rules (weights, nesting, glossy sampling) are in
// docs/rendering.md, "Reflection, refraction and glossy reflection".
#pragma once

#include "core/render/direct_lighting.h"
#include "core/render/integrator.h"
#include "core/render/medium_stack.h"
#include "materials/evaluated_surface.h"

namespace rt {

class WhittedIntegrator final : public Integrator {
 public:
  Vec3 radiance_from_hit(const Ray& ray, const SceneHit& met, int depth, TraceContext& ctx) const override;
  // The camera rays' surfaces evaluated first, then their shadow rays to the point lights traced
  // as packets (find_point_shadows), then each shaded: the same radiance as one by one.
  void radiance_from_hits(const Ray* rays, const SceneHit* met, int count, TraceContext* const* ctx,
                          Vec3* out) const override;

  // Where a ray is in its tree: passed by value, so branches never see each other's state.
  struct PathState {
    int depth = 0;       // bounces already taken
    Vec3 weight{1.0f};   // this ray's weight in the pixel: branches below kMinWeight are not traced
    MediumStack media;   // what the ray travels through
    bool split = false;  // a glossy reflection above already split the path into glossy_samples rays
    // The ray's direction is of unit length, as secondary() and spread() make every ray below a
    // hit (reflect, refract, glossy_direction): its length is then 1, not worked out (a square
    // root and a division between one hit and the next). A camera's rays need not be.
    bool unit_direction = false;
    float share = 1.0f;  // 1 / the rays a glossy split above made: with weight, the hit's part of the pixel
    uint64_t path = 0;   // where in the ray tree: keys its random numbers (core/sampling.h)
    // The ray cone (Akenine-Moller et al. 2019): width at the ray's origin and spread angle. A
    // mirror or refraction passes the width on and keeps the spread (surface curvature ignored).
    float cone_width = 0.0f;
    float cone_spread = 0.0f;
  };
  // A secondary ray whose weight in the pixel is below this is not traced (Hall and Greenberg's
  // adaptive tree depth): it bounds the ray tree of glass, whose every hit branches in two.
  static constexpr float kMinWeight = 1.0f / 512.0f;

  // The radiance arriving along `ray`, walked where the caller made it: its tmax is left at what
  // it meets. `from`: where the ray starts, if known (Scene::intersect).
  Vec3 trace(Ray& ray, const PathState& state, TraceContext& ctx, RayStart from = {}) const;
  // trace() once the ray's first meeting is known (ray.tmax at it).
  Vec3 shade(const Ray& ray, const SceneHit& met, const PathState& state, TraceContext& ctx) const;
  // Branch kinds for child_path.
  enum Branch : uint32_t { kReflected = 1, kRefracted, kGlossyRay, kGlossyRefraction, kFresnelChoice };

 private:
  // shade()'s two halves for a surface: what it is at the hit (cone_width: the ray cone's width
  // there; the camera sample's layers are recorded), then its radiance (`known`: its point
  // lights' shadows, if found before). And for a ray that met no surface.
  EvaluatedSurface surface_at(const Ray& ray, const Hit& hit, const PathState& state, TraceContext& ctx,
                              float& cone_width) const;
  Vec3 shade_surface(const Ray& ray, const EvaluatedSurface& s, float cone_width, const PathState& state,
                     TraceContext& ctx, const PointShadows* known = nullptr) const;
  Vec3 shade_no_surface(const Ray& ray, const SceneHit& met, const PathState& state, TraceContext& ctx) const;
  // The state of a camera ray's tree at its first hit.
  static PathState camera_state(int depth, const TraceContext& ctx);
  // Beer-Lambert along the segment just travelled, inside the state's innermost medium.
  // Whether there is a medium is asked here, inline: most rays travel in air, and a call for each
  // cost antialias.json 1.5% (docs/benchmark.md, "Round two, a twenty-sixth session").
  Vec3 absorbed(Vec3 radiance, const Ray& ray, const PathState& state, const Scene& scene) const {
    return state.media.empty() ? radiance : absorbed_in_medium(radiance, ray, state, scene);
  }
  // requires !state.media.empty()
  Vec3 absorbed_in_medium(Vec3 radiance, const Ray& ray, const PathState& state, const Scene& scene) const;
  // The reflected and refracted rays from `s`, which the ray along -s.wo met; `cone_width`: the
  // ray cone's width there (surface_at's), where the rays start.
  Vec3 secondary(const EvaluatedSurface& s, const PathState& state, float cone_width, TraceContext& ctx) const;
  Vec3 spread(const EvaluatedSurface& s, Vec3 centre, float width, RayKind kind, float branch_weight,
              const PathState& state, TraceContext& ctx) const;
  Vec3 traced_from(const EvaluatedSurface& s, Vec3 direction, RayKind kind, const PathState& state,
                   TraceContext& ctx) const;
};

}  // namespace rt
