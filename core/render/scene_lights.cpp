#include "core/render/scene_lights.h"

#include "materials/evaluated_surface.h"

namespace rt {
namespace {

// A point of the emissive surfaces, as a ray from `point` would meet it.
LightSample sample_surfaces(const Scene& scene, Vec3 point, float u_pick, Vec2 u, SurfaceDetailSwitches detail) {
  LightSample ls;
  const EmitterSample e = scene.emitters.sample(scene.bvh, u_pick, u);
  const Vec3 to = e.point - point;
  const float d2 = glm::dot(to, to);
  if (!(d2 > 0.0f) || !(e.area_pdf > 0.0f)) return ls;
  ls.distance = std::sqrt(d2);
  ls.direction = to / ls.distance;
  // The emitter's own record at the point, for its material and texture coordinates.
  Ray towards;
  towards.origin = point;
  towards.direction = ls.direction;
  Hit hit = e.hit;
  hit.t = ls.distance;
  const SurfaceInteraction si = scene.surface(towards, hit);
  ls.cos_light = std::fabs(glm::dot(si.geometric_normal, ls.direction));
  if (!(ls.cos_light > 0.0f)) return ls;
  ls.radiance = emitted_radiance(scene.materials()[si.material], si, ls.direction, scene.textures(), 0.0f, detail);
  ls.pdf = e.area_pdf * d2 / ls.cos_light;
  return ls;
}

LightSample sample_sky(const Environment& sky, Vec2 u) {
  LightSample ls;
  ls.distance = kInfinity;
  float pdf = 0.0f;
  if (sky.is_image() && sky.sample(u, ls.direction, ls.radiance, pdf)) ls.pdf = pdf;
  return ls;
}

}  // namespace

LightSample sample_area_li(const Scene& scene, size_t l, Vec3 point, const SampleStream& samples, uint64_t path,
                           SurfaceDetailSwitches detail, uint32_t sample) {
  const size_t n = scene.lights.size();
  if (l == n) {
    if (scene.emitters.empty()) return LightSample{};
    const Vec2 u = samples.get2(SamplePurpose::kLight, path, light_dimension(n, 2 * sample));
    const float u_pick = samples.get1(SamplePurpose::kLight, path, light_dimension(n, 2 * sample + 1));
    return sample_surfaces(scene, point, u_pick, u, detail);
  }
  if (!scene.background.is_image()) return LightSample{};
  return sample_sky(scene.background, samples.get2(SamplePurpose::kLight, path, light_dimension(n + 1, sample)));
}

float surface_pdf_li(const Scene& scene, const Hit& hit, Vec3 normal, Vec3 direction, float distance) {
  const float area_pdf = scene.emitters.area_pdf(scene.bvh, hit, normal);
  if (!(area_pdf > 0.0f)) return 0.0f;
  const float cos_light = std::fabs(glm::dot(normal, direction));
  return area_pdf * distance * distance / cos_light;
}

}  // namespace rt
