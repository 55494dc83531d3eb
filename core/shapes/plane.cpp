#include "core/shapes/plane.h"

namespace rt {

bool intersect_plane(const Ray& ray, Hit& hit) {
  if (ray.direction.y == 0.0f) return false;  // parallel: a plane has no thickness to hit
  const float t = -ray.origin.y / ray.direction.y;
  if (!(t > ray.tmin && t < ray.tmax)) return false;
  const float x = ray.origin.x + t * ray.direction.x;
  const float z = ray.origin.z + t * ray.direction.z;
  if (std::fabs(x) > 1.0f || std::fabs(z) > 1.0f) return false;
  hit.t = t;
  hit.part = 0;
  return true;
}

SurfacePatch plane_patch(Vec3 p, uint32_t /*part*/) {
  SurfacePatch s;
  s.normal = Vec3(0.0f, 1.0f, 0.0f);
  s.uv = Vec2(0.5f * (p.x + 1.0f), 0.5f * (p.z + 1.0f));
  s.dpdu = Vec3(2.0f, 0.0f, 0.0f);
  s.dpdv = Vec3(0.0f, 0.0f, 2.0f);  // towards +Z: upright seen from above, +Z towards the viewer
  return s;
}

}  // namespace rt
