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
  const int axis = static_cast<int>(part / 2);
  const bool negative = (part & 1u) != 0;
  // Cyclic axes: e_a x e_{a+1} = e_{a+2}. On the + face (u, v) follow (a+1, a+2); on the - face
  // they are swapped so that dpdu x dpdv still points outwards.
  int axis_u = (axis + 1) % 3, axis_v = (axis + 2) % 3;
  if (negative) std::swap(axis_u, axis_v);
  SurfacePatch s;
  s.normal = Vec3(0.0f);
  s.normal[axis] = negative ? -1.0f : 1.0f;
  s.uv = Vec2(0.5f * (p[axis_u] + 1.0f), 0.5f * (p[axis_v] + 1.0f));
  s.dpdu = Vec3(0.0f);
  s.dpdu[axis_u] = 2.0f;
  s.dpdv = Vec3(0.0f);
  s.dpdv[axis_v] = 2.0f;
  return s;
}

}  // namespace rt
