// Debug view: the shading normal of the closest hit mapped from [-1, 1] to [0, 1] per channel.
#pragma once

#include "core/render/integrator.h"

namespace rt {

class NormalsIntegrator final : public Integrator {
 public:
  Vec3 radiance(const Ray& camera_ray, int /*depth*/, TraceContext& ctx) const override {
    Ray ray = camera_ray;
    Hit hit;
    if (!ctx.scene.intersect(ray, hit)) return Vec3(0.0f);
    return 0.5f * (ctx.scene.surface(ray, hit).shading_normal + 1.0f);
  }
};

}  // namespace rt
