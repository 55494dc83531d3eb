// An affine object-to-world transform with its inverse and normal matrix, computed once at
// scene build time. Normals go through the inverse transpose so they stay perpendicular to the
// surface under non-uniform scale.
#pragma once

#include <optional>

#include "core/aabb.h"
#include "core/float_error.h"
#include "core/math.h"
#include "core/ray.h"

namespace rt {

struct Transform {
  Mat4 to_world{1.0f};
  Mat4 to_object{1.0f};
  Mat3 normal_to_world{1.0f};  // inverse transpose of the linear part of to_world

  // Each of these the same floats as glm's product (core/affine_lanes.h).
  Vec3 point_to_world(Vec3 p) const { return affine_point(to_world, p); }
  // The same, with the world point's error bound for a point known within +-p_error.
  Vec3 point_to_world(Vec3 p, Vec3 p_error, Vec3& world_error) const {
    world_error = transformed_point_error(to_world, p, p_error);
    return point_to_world(p);
  }
  Vec3 vector_to_world(Vec3 v) const { return linear_vector(to_world, v); }
  Vec3 normal_to_world_unit(Vec3 n) const { return glm::normalize(normal_to_world * n); }
  Vec3 point_to_object(Vec3 p) const { return affine_point(to_object, p); }
  Vec3 vector_to_object(Vec3 v) const { return linear_vector(to_object, v); }
};

// The transform for an affine matrix, or nothing when the matrix is singular (a zero scale,
// a degenerate 4x4) or not finite: such an object has no inside, no normals, no inverse.
std::optional<Transform> make_transform(const Mat4& to_world);

// `outer` after `inner`: points go through inner, then outer.
inline Transform compose(const Transform& outer, const Transform& inner) {
  return Transform{outer.to_world * inner.to_world, inner.to_object * outer.to_object,
                   outer.normal_to_world * inner.normal_to_world};
}

// The distance along a ray (in its t) that the rounding of its origin into t's object space can
// reach; `object_direction` is the ray's direction there.
inline float origin_rounding(const Transform& t, Vec3 world_origin, Vec3 object_direction) {
  const float length2 = glm::dot(object_direction, object_direction);
  if (!(length2 > 0.0f)) return 0.0f;
  return glm::dot(abs3(object_direction), transformed_point_error(t.to_object, world_origin)) / length2;
}

// The ray in the object space of `t`: origin and direction through to_object. The direction is
// not renormalised, so a t found there is the same t in world space. transformed_ray keeps the
// interval; object_ray starts it later by origin_rounding (pbrt-v4's rule): a ray leaving a
// surface (core/ray.h) must not find that surface again on this side of the rounding.
inline Ray transformed_ray(const Transform& t, const Ray& ray) {
  Ray r = ray;
  r.origin = t.point_to_object(ray.origin);
  r.direction = t.vector_to_object(ray.direction);
  return r;
}

inline Ray object_ray(const Transform& t, const Ray& ray) {
  Ray r = transformed_ray(t, ray);
  r.tmin += origin_rounding(t, ray.origin, r.direction);
  return r;
}

// Translate-rotate-scale as written in scene files: M = T * Rz * Ry * Rx * S, i.e. a point is
// scaled first, then rotated about X, then Y, then Z (degrees), then translated.
Mat4 compose_trs(Vec3 translate, Vec3 rotate_degrees, Vec3 scale);

// Bounds of a box after an affine map (Arvo's method: exact for the transformed box's corners).
Aabb transform_bounds(const Mat4& m, const Aabb& box);

}  // namespace rt
