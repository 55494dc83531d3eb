#include "core/shapes/cylinder.h"

#include "core/shapes/quadratic.h"

namespace rt {

bool intersect_unit_disc(const Ray& ray, float z_cap, double& t) {
  const double dz = ray.direction.z;
  if (dz == 0.0) return false;
  t = (z_cap - static_cast<double>(ray.origin.z)) / dz;
  if (!(t > ray.tmin && t < ray.tmax)) return false;
  const double x = ray.origin.x + t * ray.direction.x;
  const double y = ray.origin.y + t * ray.direction.y;
  return x * x + y * y <= 1.0;
}

bool side_root_in_height(const Ray& ray, double t0, double t1, double& t) {
  for (const double root : {t0, t1}) {
    const double z = ray.origin.z + root * ray.direction.z;
    if (root > ray.tmin && root < ray.tmax && z >= 0.0 && z <= 1.0) {
      t = root;
      return true;
    }
  }
  return false;
}

bool intersect_cylinder(const Ray& ray, Hit& hit) {
  const double ox = ray.origin.x, oy = ray.origin.y;
  const double dx = ray.direction.x, dy = ray.direction.y;
  double best = HUGE_VAL;
  uint32_t part = kCylinderSide;
  double t0, t1;
  const double a = dx * dx + dy * dy;  // 0 when the ray is parallel to the axis: no side hit
  if (a > 0.0 && solve_quadratic(a, 2.0 * (ox * dx + oy * dy), ox * ox + oy * oy - 1.0, t0, t1))
    side_root_in_height(ray, t0, t1, best);
  double tc;
  if (intersect_unit_disc(ray, 0.0f, tc) && tc < best) {
    best = tc;
    part = kCylinderBase;
  }
  if (intersect_unit_disc(ray, 1.0f, tc) && tc < best) {
    best = tc;
    part = kCylinderTop;
  }
  if (best == HUGE_VAL) return false;
  hit.t = static_cast<float>(best);
  hit.part = part;
  return true;
}

SurfacePatch cap_patch(Vec3 p, bool top) {
  SurfacePatch s;
  s.normal = cap_normal(top);
  s.uv = Vec2(0.5f * (top ? 1.0f + p.x : 1.0f - p.x), 0.5f * (1.0f - p.y));
  s.dpdu = Vec3(top ? 2.0f : -2.0f, 0.0f, 0.0f);
  s.dpdv = Vec3(0.0f, -2.0f, 0.0f);
  return s;
}

SurfacePatch cylinder_patch(Vec3 p, uint32_t part) {
  if (part != kCylinderSide) return cap_patch(p, part == kCylinderTop);
  SurfacePatch s;
  const float phi = angle_around_z(p);
  const Vec3 radial = radial_towards(p);
  s.normal = radial;
  s.uv = Vec2(phi / (2.0f * kPi), 1.0f - p.z);
  s.dpdu = 2.0f * kPi * Vec3(-radial.y, radial.x, 0.0f);
  s.dpdv = Vec3(0.0f, 0.0f, -1.0f);
  return s;
}

}  // namespace rt
