#include "core/shapes/cone.h"

#include "core/shapes/quadratic.h"

namespace rt {

bool intersect_cone(const Ray& ray, Hit& hit) {
  const double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
  const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  double best = HUGE_VAL;
  uint32_t part = kConeSide;
  double t0, t1;
  // a == 0 when the ray runs parallel to a line of the cone; solve_quadratic then solves the
  // remaining linear equation. Roots below z = 0 belong to the mirrored nappe: rejected.
  const double a = dx * dx + dy * dy - dz * dz;
  if (solve_quadratic(a, 2.0 * (ox * dx + oy * dy - oz * dz), ox * ox + oy * oy - oz * oz, t0, t1))
    side_root_in_height(ray, t0, t1, best);
  double tc;
  if (intersect_unit_disc(ray, 1.0f, tc) && tc < best) {
    best = tc;
    part = kConeBase;
  }
  if (best == HUGE_VAL) return false;
  hit.t = static_cast<float>(best);
  hit.part = part;
  return true;
}

SurfacePatch cone_patch(Vec3 p, uint32_t part) {
  if (part == kConeBase) return cap_patch(p, true);
  SurfacePatch s;
  const float phi = angle_around_z(p);
  const Vec3 radial = radial_towards(p);
  s.normal = cone_side_normal(radial);
  const float z = std::max(p.z, 0.0f);
  s.uv = Vec2(1.0f - phi / (2.0f * kPi), z);
  s.dpdu = -2.0f * kPi * z * Vec3(-radial.y, radial.x, 0.0f);  // vanishes at the apex
  s.dpdv = Vec3(radial.x, radial.y, 1.0f);
  return s;
}

}  // namespace rt
