// Bvh::build_quads: each leaf of triangles alone copied into quads, four triangles a quad in slot
// order (the last one padded with lanes that are never hit), so that traversal tests a leaf's
// triangles four at a time (core/accel/triangle_quad.h) and finds exactly what the one-at-a-time
// loop would: the nearest, the first of equals in slot order.
#include "core/accel/bvh.h"

namespace rt {
namespace {

// Smaller leaves stay one triangle at a time: a quad is three cache lines, two triangles' slots
// fewer, and incoherent rays pay for every line they touch.
constexpr uint32_t kMinQuadLeaf = 3;

}  // namespace

void Bvh::build_quads() {
  leaf_quads_.assign(slots_.size(), kNoQuads);
  const auto add_leaf = [&](uint32_t ref) {
    const uint32_t first = BvhRef::first(ref), count = BvhRef::count(ref);
    if (count < kMinQuadLeaf) return;
    for (uint32_t s = first; s < first + count; ++s)
      if (slots_[s].id >= triangle_count_) return;  // shapes, instances and CSG keep their own tests
    leaf_quads_[first] = static_cast<uint32_t>(quads_.size());
    for (uint32_t s = first; s < first + count; s += 4) {
      TriangleQuad quad{};  // zero edges in the lanes left over: never hit
      for (uint32_t lane = 0; lane < 4 && s + lane < first + count; ++lane)
        set_quad_lane(quad, static_cast<int>(lane), slots_[s + lane].triangle);
      quads_.push_back(quad);
    }
  };
  if (slots_.empty()) return;
  if (BvhRef::is_leaf(root_)) add_leaf(root_);
  for (const BvhNode& node : nodes_)
    for (int slot = 0; slot < kBvhWidth; ++slot)
      if (node.bounds[0][slot] <= node.bounds[1][slot] && BvhRef::is_leaf(node.child[slot])) add_leaf(node.child[slot]);
}

}  // namespace rt
