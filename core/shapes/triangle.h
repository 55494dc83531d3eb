// Triangle in the layout the hot path wants: one vertex and two edges, precomputed once,
// 36 bytes, intersected with the Moller-Trumbore test.
#pragma once

#include "core/aabb.h"
#include "core/hit.h"
#include "core/ray.h"

namespace rt {

struct PackedTriangle {
  Vec3 v0;
  Vec3 e1;  // v1 - v0
  Vec3 e2;  // v2 - v0

  static PackedTriangle from_vertices(Vec3 a, Vec3 b, Vec3 c) { return {a, b - a, c - a}; }
  // False when a vertex or an edge overflowed (vertices beyond +-1.7e38 can have infinite edges).
  bool is_finite() const { return rt::is_finite(v0) && rt::is_finite(e1) && rt::is_finite(e2); }
  Aabb bounds() const {
    Aabb b;
    b.extend(v0);
    b.extend(v0 + e1);
    b.extend(v0 + e2);
    return b;
  }
};

// Updates hit (t, b1, b2) and returns true if the triangle is hit inside (ray.tmin, ray.tmax).
// Both faces count: shading decides what the back of a triangle looks like.
inline bool intersect_triangle(const PackedTriangle& tri, const Ray& ray, Hit& hit) {
  // All conditions are evaluated and combined into one branch: with incoherent rays each
  // early-out branch would be mispredicted half the time, which costs more than the arithmetic.
  const Vec3 p = glm::cross(ray.direction, tri.e2);
  const float det = glm::dot(tri.e1, p);
  const float inv_det = 1.0f / det;  // +-inf for a parallel ray: then b1, b2 or t are NaN or inf
  const Vec3 s = ray.origin - tri.v0;
  const float b1 = glm::dot(s, p) * inv_det;
  const Vec3 q = glm::cross(s, tri.e1);
  const float b2 = glm::dot(ray.direction, q) * inv_det;
  const float t = glm::dot(tri.e2, q) * inv_det;
  const bool inside = (det != 0.0f) & (b1 >= 0.0f) & (b2 >= 0.0f) & (b1 + b2 <= 1.0f) & (t > ray.tmin) & (t < ray.tmax);
  if (!inside) return false;
  hit.t = t;
  hit.b1 = b1;
  hit.b2 = b2;
  hit.part = 0;
  return true;
}

}  // namespace rt
