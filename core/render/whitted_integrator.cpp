#include "core/render/whitted_integrator.h"

#include "materials/phong.h"

namespace rt {

Vec3 direct_lighting(const SurfaceInteraction& si, Vec3 n, Vec3 ng, Vec3 v, TraceContext& ctx) {
  const Scene& scene = ctx.scene;
  const Material& m = scene.materials[si.material];
  Vec3 sum = scene.ambient * m.kd;
  for (const Light& light : scene.lights) {
    const LightSample ls = sample_light(light, si.position);
    // A light behind the geometric surface cannot reach it, whatever the shading normal says.
    if (glm::dot(ng, ls.direction) <= 0.0f || glm::dot(n, ls.direction) <= 0.0f) continue;
    Ray shadow;
    shadow.origin = offset_ray_origin(si.position, ng, ls.direction);
    shadow.direction = ls.direction;
    // Stop just short of the light so a surface the light sits on does not shadow it.
    shadow.tmax = ls.distance * (1.0f - kRayOffsetScale);
    ++ctx.counters[RayKind::kShadow];
    if (scene.occluded(shadow)) continue;
    sum += ls.radiance * phong_reflectance(m, n, ls.direction, v);
  }
  return sum;
}

Vec3 WhittedIntegrator::radiance(const Ray& camera_ray, int /*depth*/, TraceContext& ctx) const {
  Ray ray = camera_ray;
  Hit hit;
  if (!ctx.scene.intersect(ray, hit)) return ctx.scene.background;
  const SurfaceInteraction si = ctx.scene.surface(ray, hit);
  // Shade the side the ray sees: both sides of a surface are lit like its front.
  const float side = si.front_face ? 1.0f : -1.0f;
  const Vec3 v = -glm::normalize(ray.direction);
  return direct_lighting(si, side * si.shading_normal, side * si.geometric_normal, v, ctx);
}

}  // namespace rt
