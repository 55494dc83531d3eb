// The BVH builder's binary tree (core/accel/bvh_build.cpp), and its collapse into the wide nodes
// traversal reads (core/accel/bvh_collapse.cpp). Internal to core/accel.
#pragma once

#include <cstdint>
#include <vector>

#include "core/accel/bvh.h"
#include "core/fill_vector.h"

namespace rt {

struct BinaryNode {
  Aabb bounds;
  uint32_t offset = 0;  // interior: index of the right child (the left one follows its parent); leaf: first slot
  uint32_t count = 0;   // 0 for interior nodes
};

// Half the surface area of a box, in double: extents up to 2 x 3.4e38 and their products stay
// finite. 0 for an empty box.
inline double half_area(float lo_x, float hi_x, float lo_y, float hi_y, float lo_z, float hi_z) {
  if (!(lo_x <= hi_x)) return 0.0;
  const double x = double(hi_x) - lo_x, y = double(hi_y) - lo_y, z = double(hi_z) - lo_z;
  return x * y + y * z + z * x;
}
inline double half_area(const Aabb& b) { return half_area(b.lo.x, b.hi.x, b.lo.y, b.hi.y, b.lo.z, b.hi.z); }

// The binary tree `binary` (root at 0) as kBvhWidth-wide nodes appended to `out`: each adopts its
// children, then repeatedly replaces the interior child with the largest surface area by that
// child's two children. Returns the root's reference. Nodes come depth first, a node before its
// children's subtrees in slot order, whatever the thread count: the root's children's subtrees
// are collapsed on `threads` threads, each into its place (its nodes counted first).
uint32_t collapse_binary_tree(const std::vector<BinaryNode>& binary, unsigned threads, FillVector<BvhNode>& out);

}  // namespace rt
