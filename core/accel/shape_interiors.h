// What a ray inside a closed shape can meet before it leaves. A sphere, box, cylinder or cone is
// convex: a ray that starts inside it (a refraction into glass, a reflection within it) runs
// inside its box until it crosses its surface, so only the primitives whose boxes reach that box
// can be met first. Where those are a few analytic shapes (a ball resting on a floor: the floor),
// testing them and the shape finds the hit the walk would find (the same tests and the same order
// of hits, `precedes`), without the walk (Bvh::intersect_from_inside).
#pragma once

#include <cstdint>
#include <vector>

#include "core/aabb.h"

namespace rt {

class Bvh;

struct ShapeInterior {
  static constexpr uint32_t kMaxOthers = 3;  // more, and the walk is as cheap
  static constexpr uint32_t kUnusable = 0xffffffffu;
  // The shape's world box grown by far more than any rounding (a ten-thousandth of its size and
  // of its distance from the origin): a ray whose origin and hit on the shape lie in it stays in it.
  Aabb box;
  uint32_t count = kUnusable;     // how many others, or kUnusable: not closed, or too many to test
  uint32_t others[kMaxOthers]{};  // the analytic shapes whose boxes meet twice that margin
  bool usable() const { return count <= kMaxOthers; }
};

// One per analytic shape of `bvh` (its shape ids in order), from its built tree.
std::vector<ShapeInterior> find_shape_interiors(const Bvh& bvh);

}  // namespace rt
