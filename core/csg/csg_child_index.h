// The children of one CSG operation in a small tree of boxes of their own, so that a line through
// a solid of thousands of operands tests the few whose boxes it meets, not every one (5,000
// operands cost every ray 5,000 box tests and span merges: 55 us a ray, 8 s for a 32 x 24 image
// in the report of issue 36). CsgObject builds one for each operation of kMinIndexedChildren
// children or more; the children met come back in their own order, so the solid's spans are the
// ones the plain loop over every child finds, bit for bit.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/aabb.h"
#include "core/ray.h"

namespace rt {

// The stretch of a ray's line whose CSG boundaries a query uses. Spans are found along the whole
// line (a ray that starts inside a solid must find where it leaves), but an operand whose box the
// line meets only outside [lo, hi] has no boundary there, and union, merge, intersection and
// difference all act point by point: leaving it out changes the result only outside [lo, hi].
struct CsgReach {
  Ray line;  // the ray with its interval ignored
  float lo = -kInfinity, hi = kInfinity;

  // The whole line: every span of the solid.
  static CsgReach whole(const Ray& ray);
  // The ray's interval, widened by far more than rounding: a box's distances along the line and a
  // boundary's own are worked out apart, and a boundary just inside the interval must not be lost.
  static CsgReach of(const Ray& ray);
};

// Whether the line meets the box within [reach.lo, reach.hi]. Monotone in the box: a line that
// meets a box meets every box around it, so a tree of boxes never loses a child.
inline bool reach_meets_box(const Aabb& box, const CsgReach& reach) {
  if (box.empty()) return false;
  const Ray& line = reach.line;
  float t0 = reach.lo, t1 = reach.hi;
  for (int a = 0; a < 3; ++a) {
    const float o = line.origin[a], d = line.direction[a];
    if (d == 0.0f) {
      if (o < box.lo[a] || o > box.hi[a]) return false;
      continue;
    }
    float ta = (box.lo[a] - o) / d, tb = (box.hi[a] - o) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

class CsgChildIndex {
 public:
  // Operations with fewer children are walked child by child: a handful of box tests is cheaper.
  static constexpr uint32_t kMinIndexedChildren = 16;

  // `children`: the operation's child node indices, ascending; `bounds[i]`: child i's box.
  CsgChildIndex(const std::vector<uint32_t>& children, const std::vector<Aabb>& bounds);

  // The children whose boxes the line meets within the reach, ascending, into out[0..capacity);
  // their count, or -1 when more than `capacity` do (the caller then walks every child).
  int met(const CsgReach& reach, uint32_t* out, int capacity) const;
  // How many children the operation has.
  uint32_t size() const { return static_cast<uint32_t>(items_.size()); }

 private:
  struct Box {
    Aabb bounds;
    uint32_t first =
        0;  // a leaf: its children in items_[first, first + count); else its two boxes, first and first + 1
    uint32_t count = 0;
  };
  struct Item {
    uint32_t child;
    Aabb bounds;
  };
  static constexpr uint32_t kLeafSize = 4;
  static constexpr int kMaxDepth = 48;

  void build(uint32_t box, uint32_t begin, uint32_t end, int depth);

  std::vector<Box> boxes_;
  std::vector<Item> items_;
};

}  // namespace rt
