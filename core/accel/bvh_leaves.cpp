// Bvh::fill_leaves: what the leaves hold, once the tree's shape is known. A leaf of three or more
// triangles alone becomes a quad leaf: its triangles copied into quads, four a quad in build order
// (the last one padded with lanes that are never hit), with their ids; traversal then tests them
// four at a time (core/accel/triangle_quad.h) and finds exactly what the one-at-a-time loop would:
// the nearest, equals ordered by id (core/accel/bvh_kernels_impl.h, precedes). Every other leaf
// (shapes, instances, CSG solids, one or two triangles) gets slots: each primitive's id and a
// triangle's copy. Each array holds only its own leaves' primitives: a mesh's slots would
// otherwise copy every triangle a second time, never read (12 MB for 300k triangles).
#include "core/accel/bvh.h"

#include "core/parallel_for.h"

namespace rt {
namespace {

// Smaller leaves stay one triangle at a time: a quad is three cache lines, two triangles' slots
// fewer, and incoherent rays pay for every line they touch.
constexpr uint32_t kMinQuadLeaf = 3;

}  // namespace

void Bvh::fill_leaves(const PrimitiveSet& prims, const uint32_t* order, unsigned threads) {
  // Every leaf reference, the root's and the nodes' used slots, in one fixed order.
  std::vector<uint32_t*> leaves;
  if (BvhRef::is_leaf(root_)) leaves.push_back(&root_);
  for (BvhNode& node : nodes_)
    for (int slot = 0; slot < kBvhWidth; ++slot)
      if (child_used(node, slot) && BvhRef::is_leaf(node.child[slot])) leaves.push_back(&node.child[slot]);
  // Which leaves become quad leaves (enough triangles and nothing else), and where each leaf's
  // quads or slots start: running sums in leaf order, so the arrays are the same whatever the
  // thread count.
  std::vector<uint32_t> first_quad(leaves.size() + 1, 0), first_slot(leaves.size() + 1, 0);
  for (size_t k = 0; k < leaves.size(); ++k) {
    const uint32_t ref = *leaves[k];
    const uint32_t first = BvhRef::first(ref), count = BvhRef::count(ref);
    bool quads = count >= kMinQuadLeaf;
    for (uint32_t s = first; quads && s < first + count; ++s)
      quads = kind(order[s]) == PrimitiveKind::kTriangle;  // shapes, instances and CSG keep their own tests
    first_quad[k + 1] = first_quad[k] + (quads ? BvhRef::quad_count(ref) : 0);
    first_slot[k + 1] = first_slot[k] + (quads ? 0 : count);
  }
  // Each quad and slot written in full on the thread that fills its leaf.
  quads_.resize(first_quad.back());
  slots_.resize(first_slot.back());
  parallel_for(leaves.size(), threads, 256, [&](unsigned, size_t k) {
    const uint32_t ref = *leaves[k];
    const uint32_t* ids = order + BvhRef::first(ref);
    const uint32_t count = BvhRef::count(ref);
    if (first_quad[k + 1] == first_quad[k]) {
      for (uint32_t j = 0; j < count; ++j) {
        const uint32_t id = ids[j];
        slots_[first_slot[k] + j] =
            Slot{kind(id) == PrimitiveKind::kTriangle ? prims.triangles[id] : PackedTriangle{}, id};
      }
      return;
    }
    uint32_t q = first_quad[k];
    for (uint32_t s = 0; s < count; s += 4) {
      TriangleQuad quad{};  // zero edges in the lanes left over: never hit
      for (int lane = 0; lane < 4; ++lane) quad.id[lane] = ~0u;
      for (uint32_t lane = 0; lane < 4 && s + lane < count; ++lane)
        set_quad_lane(quad, static_cast<int>(lane), prims.triangles[ids[s + lane]], ids[s + lane]);
      quads_[q++] = quad;
    }
  });
  for (size_t k = 0; k < leaves.size(); ++k) {
    const uint32_t count = BvhRef::count(*leaves[k]);
    *leaves[k] = first_quad[k + 1] > first_quad[k] ? BvhRef::quad_leaf(first_quad[k], count)
                                                   : BvhRef::leaf(first_slot[k], count);
  }
}

}  // namespace rt
