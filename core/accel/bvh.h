// Bounding volume hierarchy over a PrimitiveSet: binned surface-area-heuristic build, stored as
// a flat array of 32-byte nodes in depth-first order (left child follows its parent), traversed
// with a fixed-size stack, near child first. No allocation and no virtual call per ray.
#pragma once

#include <cstdint>
#include <vector>

#include "core/accel/primitives.h"

namespace rt {

struct BvhNode {
  Vec3 lo;
  uint32_t offset;  // interior: index of the right child; leaf: first slot in the primitive order
  Vec3 hi;
  uint16_t count;   // 0 for an interior node, else number of primitives in the leaf
  uint8_t axis;     // split axis of an interior node: picks which child is nearer
  uint8_t pad = 0;
};
static_assert(sizeof(BvhNode) == 32, "BvhNode must stay 32 bytes: two per cache line");

struct BvhBuildOptions {
  unsigned threads = 1;  // subtrees are built in parallel; the result does not depend on this
};

struct BvhStats {
  size_t nodes = 0;
  size_t leaves = 0;
  int max_depth = 0;
  double sah_cost = 0.0;
};

class Bvh {
 public:
  Bvh() = default;
  Bvh(PrimitiveSet prims, const BvhBuildOptions& options);

  // Closest hit in (ray.tmin, ray.tmax); narrows ray.tmax to it.
  bool intersect(Ray& ray, Hit& hit) const;
  // Whether anything is hit in (ray.tmin, ray.tmax): stops at the first hit found.
  bool occluded(const Ray& ray) const;

  const PrimitiveSet& primitives() const { return prims_; }
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  Aabb bounds() const;
  BvhStats stats() const;

  // Deepest tree the builder produces; the traversal stack is sized from it.
  static constexpr int kMaxDepth = 64;

 private:
  template <bool kAnyHit>
  bool traverse(Ray& ray, Hit& hit) const;

  PrimitiveSet prims_;
  std::vector<BvhNode> nodes_;
  std::vector<uint32_t> order_;                // slot -> primitive id
  std::vector<PackedTriangle> slot_triangles_;  // slot -> triangle copy, so leaves read memory in order
};

}  // namespace rt
