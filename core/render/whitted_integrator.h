// Whitted-style direct lighting: ambient + for every light, Phong diffuse and specular times a
// hard shadow test. Secondary rays (reflection, refraction) extend this integrator next.
#pragma once

#include "core/render/integrator.h"

namespace rt {

class WhittedIntegrator final : public Integrator {
 public:
  Vec3 radiance(const Ray& ray, int depth, TraceContext& ctx) const override;
};

// Direct light reaching `si` from every light, with hard shadows, through the hit's material.
// v points from the surface to the viewer; n and ng are already turned to face the viewer.
Vec3 direct_lighting(const SurfaceInteraction& si, Vec3 n, Vec3 ng, Vec3 v, TraceContext& ctx);

}  // namespace rt
