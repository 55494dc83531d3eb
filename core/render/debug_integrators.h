// Debug views of the closest hit, one colour per pixel, no lighting (`--integrator NAME`):
//   normals  shading normal mapped from [-1, 1] to [0, 1] per channel;
//   uv       the surface's texture coordinates: red = u, green = v (each wrapped into [0, 1));
//   depth    distance from the camera, linear from white at the nearest point of the scene's
//            bounds to black at their farthest corner;
//   albedo   the evaluated diffuse colour (kd, less what the material transmits).
// Like every integrator they fill the camera sample's layers (core/render/aovs.h) when asked.
// An area light's face seen first is drawn as a surface would be (its normal, its coordinates
// along its edges, its distance; no albedo: black). A ray that hits nothing is black. One
// class, parameterised by the view of the hit.
#pragma once

#include "core/render/integrator.h"
#include "materials/evaluated_surface.h"

namespace rt {

struct DebugHit {
  Ray ray;  // the camera ray
  SurfaceInteraction surface;
  float distance = 0.0f;  // from the ray's origin
  bool light = false;     // an area light's face: `surface` has its normal and uv, no material
};

inline Vec3 black() { return Vec3(0.0f); }

template <Vec3 (*View)(const DebugHit&, const Scene&)>
class DebugIntegrator final : public Integrator {
 public:
  Vec3 radiance_from_hit(const Ray& camera_ray, const SceneHit& met, int /*depth*/, TraceContext& ctx) const override {
    DebugHit h{camera_ray, {}, 0.0f, false};
    if (!met.surface && !met.light) {
      record_no_hit(ctx, Vec3(0.0f));
      return black();
    }
    h.distance = (met.light ? h.ray.tmax : met.hit.t) * glm::length(h.ray.direction);
    if (met.light) {
      h.light = true;
      h.surface.shading_normal = met.light->normal();
      h.surface.texcoord[0].uv = met.light_uv;
      record_first_hit(ctx, Vec3(0.0f), h.surface.shading_normal, h.distance, Vec3(0.0f));
    } else {
      h.surface = ctx.scene.surface(h.ray, met.hit, Scene::Texcoords::kAlways);  // the uv view shows them
      if (ctx.aovs) {
        const EvaluatedSurface s = evaluate_surface(ctx.scene.materials()[h.surface.material], h.surface,
                                                    h.ray.direction, ctx.scene.textures());
        record_first_hit(ctx, s.diffuse, s.n, h.distance, Vec3(0.0f));
      }
    }
    return View(h, ctx.scene);
  }
};

inline Vec3 normals_view(const DebugHit& h, const Scene&) { return 0.5f * (h.surface.shading_normal + 1.0f); }

inline Vec3 uv_view(const DebugHit& h, const Scene&) {
  const Vec2 uv = h.surface.texcoord[0].uv - glm::floor(h.surface.texcoord[0].uv);
  return Vec3(uv.x, uv.y, 0.0f);
}

inline Vec3 depth_view(const DebugHit& h, const Scene& scene) {
  // White at the scene's nearest point to the camera, black at its farthest corner: the whole
  // range of grey spans the scene, wherever the camera is.
  const Aabb b = scene.bvh.bounds();
  const Vec3 o = h.ray.origin;
  const float nearest = glm::length(glm::max(glm::max(b.lo - o, o - b.hi), Vec3(0.0f)));
  float farthest = 0.0f;
  for (int c = 0; c < 8; ++c)
    farthest = std::max(
        farthest, glm::length(Vec3(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z) - o));
  if (!(farthest > nearest)) return Vec3(1.0f);
  return Vec3(std::clamp(1.0f - (h.distance - nearest) / (farthest - nearest), 0.0f, 1.0f));
}

inline Vec3 albedo_view(const DebugHit& h, const Scene& scene) {
  if (h.light) return Vec3(0.0f);
  return evaluate_surface(scene.materials()[h.surface.material], h.surface, h.ray.direction, scene.textures()).diffuse;
}

using NormalsIntegrator = DebugIntegrator<normals_view>;
using UvIntegrator = DebugIntegrator<uv_view>;
using DepthIntegrator = DebugIntegrator<depth_view>;
using AlbedoIntegrator = DebugIntegrator<albedo_view>;

}  // namespace rt
