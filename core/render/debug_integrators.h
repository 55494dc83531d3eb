// Debug views of the closest hit, one colour per pixel, no lighting (`--integrator NAME`):
//   normals  shading normal mapped from [-1, 1] to [0, 1] per channel;
//   uv       the surface's texture coordinates: red = u, green = v (each wrapped into [0, 1));
//   depth    distance from the camera, white near to black at the farthest corner of the scene's
//            bounds (linear);
//   albedo   the evaluated diffuse colour (kd, less what the material transmits).
// A ray that hits nothing is black.
#pragma once

#include "core/render/integrator.h"
#include "materials/evaluated_surface.h"

namespace rt {

// The closest hit of a camera ray, or false.
inline bool debug_hit(const Ray& camera_ray, TraceContext& ctx, SurfaceInteraction& si, float& distance) {
  Ray ray = camera_ray;
  Hit hit;
  if (!ctx.scene.intersect(ray, hit)) return false;
  si = ctx.scene.surface(ray, hit);
  distance = hit.t * glm::length(ray.direction);
  return true;
}

class NormalsIntegrator final : public Integrator {
 public:
  Vec3 radiance(const Ray& ray, int /*depth*/, TraceContext& ctx) const override {
    SurfaceInteraction si;
    float distance;
    return debug_hit(ray, ctx, si, distance) ? 0.5f * (si.shading_normal + 1.0f) : Vec3(0.0f);
  }
};

class UvIntegrator final : public Integrator {
 public:
  Vec3 radiance(const Ray& ray, int /*depth*/, TraceContext& ctx) const override {
    SurfaceInteraction si;
    float distance;
    if (!debug_hit(ray, ctx, si, distance)) return Vec3(0.0f);
    const Vec2 uv = si.uv - glm::floor(si.uv);
    return Vec3(uv.x, uv.y, 0.0f);
  }
};

class DepthIntegrator final : public Integrator {
 public:
  Vec3 radiance(const Ray& ray, int /*depth*/, TraceContext& ctx) const override {
    SurfaceInteraction si;
    float distance;
    if (!debug_hit(ray, ctx, si, distance)) return Vec3(0.0f);
    const Aabb b = ctx.scene.bvh.bounds();
    float farthest = 0.0f;
    for (int c = 0; c < 8; ++c)
      farthest = std::max(
          farthest,
          glm::length(Vec3(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z) - ray.origin));
    return Vec3(farthest > 0.0f ? std::clamp(1.0f - distance / farthest, 0.0f, 1.0f) : 0.0f);
  }
};

class AlbedoIntegrator final : public Integrator {
 public:
  Vec3 radiance(const Ray& ray, int /*depth*/, TraceContext& ctx) const override {
    SurfaceInteraction si;
    float distance;
    if (!debug_hit(ray, ctx, si, distance)) return Vec3(0.0f);
    return evaluate_surface(ctx.scene.materials[si.material], si, ray.direction).diffuse;
  }
};

}  // namespace rt
