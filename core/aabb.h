// Axis-aligned bounding box. Empty boxes have lo = +inf, hi = -inf so that extend() needs no branch.
#pragma once

#include "core/math.h"

namespace rt {

struct Aabb {
  Vec3 lo{kInfinity};
  Vec3 hi{-kInfinity};

  void extend(Vec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void extend(const Aabb& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  // Whether p is in the box (its faces included; false for a NaN).
  bool contains(Vec3 p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
  // Whether the two boxes share a point (touching counts).
  bool meets(const Aabb& b) const {
    return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y && lo.z <= b.hi.z && b.lo.z <= hi.z;
  }
  Vec3 extent() const { return hi - lo; }
  Vec3 centre() const { return 0.5f * (lo + hi); }
  int largest_axis() const {
    const Vec3 e = extent();
    return (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
  }
};

}  // namespace rt
