#include "core/render/direct_lighting.h"

#include "core/render/shadow_transmittance.h"
#include "materials/phong.h"

namespace rt {

Vec3 direct_lighting(const EvaluatedSurface& s, TraceContext& ctx) {
  const Scene& scene = ctx.scene;
  Vec3 sum = scene.ambient * s.diffuse;
  for (const Light& light : scene.lights) {
    const LightSample ls = sample_light(light, s.position);
    // A light behind the geometric surface cannot reach it, whatever the shading normal says.
    if (glm::dot(s.ng, ls.direction) <= 0.0f || glm::dot(s.n, ls.direction) <= 0.0f) continue;
    Ray shadow;
    shadow.origin = offset_ray_origin(s.position, s.ng, ls.direction);
    shadow.direction = ls.direction;
    // Stop just short of the light so a surface the light sits on does not shadow it.
    shadow.tmax = ls.distance * (1.0f - kRayOffsetScale);
    ++ctx.counters[RayKind::kShadow];
    const Vec3 visible = shadow_transmittance(scene, shadow);
    if (max_component(visible) <= 0.0f) continue;
    sum += visible * ls.radiance * phong_reflectance(s.diffuse, s.specular, s.shininess, s.n, ls.direction, s.wo);
  }
  return sum;
}

}  // namespace rt
