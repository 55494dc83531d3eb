// A ray with the parametric interval [tmin, tmax] it may be hit in. Intersection routines
// narrow tmax as they find closer hits, so the interval is also the "closest so far".
#pragma once

#include "core/float_error.h"
#include "core/math.h"

namespace rt {

struct Ray {
  Vec3 origin{0.0f};
  Vec3 direction{0.0f, 0.0f, -1.0f};  // not necessarily unit length
  float tmin = 0.0f;
  float tmax = kInfinity;

  // Written out (not left to C++20's parenthesised aggregates): Ray(o, d) builds with clang 14 too.
  Ray() = default;
  Ray(Vec3 o, Vec3 d, float t0 = 0.0f, float t1 = kInfinity) : origin(o), direction(d), tmin(t0), tmax(t1) {}

  Vec3 at(float t) const { return origin + t * direction; }
};

// Whether a traversal may walk the ray. A NaN or infinite origin or direction (a camera's numbers
// that overflow, a degenerate transform) makes the box tests NaN, which the NaN-proof slab test
// reads as "enter": every child slot, the unused ones too, and the walk leaves the tree. Every
// traversal (single, packet, any-hit, every instruction set) answers such a ray with a miss.
inline bool is_traceable(const Ray& r) { return is_finite(r.origin) && is_finite(r.direction) && r.tmin <= r.tmax; }

// Where every secondary ray starts (pbrt-v4's rule, section 6.8.6): the hit point moved off the
// surface along its geometric normal, to the side the ray leaves towards, by just the distance
// its rounding error could reach (p_error: an absolute bound per component, from the
// intersection and the transform to world space), then rounded away from the surface. So a ray
// never finds the surface it starts on again, yet a blocker a hair above the surface (a contact
// shadow, a grazing bump) still stops it: the offset is a few ulps of the point, not a fixed
// distance in scene units.
inline Vec3 offset_ray_origin(Vec3 p, Vec3 p_error, Vec3 geometric_normal, Vec3 direction) {
  const Vec3 n = glm::dot(direction, geometric_normal) < 0.0f ? -geometric_normal : geometric_normal;
  Vec3 po = p + glm::dot(abs3(n), p_error) * n;
  // Then one float further along the normal, so that the sum's own rounding cannot undo the move
  // (pbrt-v4). Stepping by the normal's sign rather than the offset's also moves a point known
  // exactly (no error: a plane through the origin), whose ray would otherwise start on the
  // surface and test it to find nothing, costing a box and a shape test per shadow ray.
  // A coordinate at zero would step to a subnormal, which every box test of the ray then pays
  // for in microcode (a third of a soft-shadow render, measured): it steps to the smallest
  // normal float instead.
  constexpr float kSmallest = std::numeric_limits<float>::min();
  for (int i = 0; i < 3; ++i) {
    if (n[i] > 0.0f) po[i] = std::max(next_float_up(po[i]), std::fabs(po[i]) < kSmallest ? kSmallest : -kInfinity);
    else if (n[i] < 0.0f)
      po[i] = std::min(next_float_down(po[i]), std::fabs(po[i]) < kSmallest ? -kSmallest : kInfinity);
  }
  return po;
}

// A shadow ray stops this fraction of the way short of the light, so that a surface the light
// sits on (a lamp on a ceiling) does not shadow it.
inline constexpr float kShadowEpsilon = 1e-4f;

}  // namespace rt
