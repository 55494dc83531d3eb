#include "core/shapes/cube.h"

namespace rt {

bool intersect_cube(const Ray& ray, Hit& hit) {
  double t_near = -HUGE_VAL, t_far = HUGE_VAL;
  int near_axis = -1, far_axis = -1;
  for (int a = 0; a < 3; ++a) {
    const double o = ray.origin[a], d = ray.direction[a];
    if (d == 0.0) {
      if (o < -1.0 || o > 1.0) return false;  // parallel to the slab and outside it
      continue;
    }
    double t0 = (-1.0 - o) / d, t1 = (1.0 - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_near) {
      t_near = t0;
      near_axis = a;
    }
    if (t1 < t_far) {
      t_far = t1;
      far_axis = a;
    }
  }
  if (t_near > t_far || near_axis < 0) return false;
  if (t_near > ray.tmin && t_near < ray.tmax) {  // entering from outside
    hit.t = static_cast<float>(t_near);
    hit.part = static_cast<uint32_t>(2 * near_axis + (ray.direction[near_axis] > 0.0f ? 1 : 0));
    return true;
  }
  if (t_far > ray.tmin && t_far < ray.tmax) {  // leaving from inside
    hit.t = static_cast<float>(t_far);
    hit.part = static_cast<uint32_t>(2 * far_axis + (ray.direction[far_axis] > 0.0f ? 0 : 1));
    return true;
  }
  return false;
}

SurfacePatch cube_patch(Vec3 p, uint32_t part) {
  const CubeFace face = cube_face(part);
  const Vec3 right = face.right, down = face.down;
  SurfacePatch s;
  s.normal = cube_normal(face);
  s.uv = Vec2(0.5f * (1.0f + glm::dot(p, right)), 0.5f * (1.0f + glm::dot(p, down)));
  s.dpdu = 2.0f * right;
  s.dpdv = 2.0f * down;
  return s;
}

}  // namespace rt
