// Bvh::build_quads: each leaf of three or more triangles alone copied into quads, four triangles a
// quad in slot order (the last one padded with lanes that are never hit), with their ids, and its
// reference turned into a quad leaf (BvhRef::quad_leaf). Traversal then tests the leaf's triangles
// four at a time (core/accel/triangle_quad.h) and finds exactly what the one-at-a-time loop would:
// the nearest, equals ordered by id (core/accel/bvh_kernels_impl.h, precedes).
#include "core/accel/bvh.h"

#include "core/parallel_for.h"

namespace rt {
namespace {

// Smaller leaves stay one triangle at a time: a quad is three cache lines, two triangles' slots
// fewer, and incoherent rays pay for every line they touch.
constexpr uint32_t kMinQuadLeaf = 3;

}  // namespace

void Bvh::build_quads(unsigned threads) {
  if (slots_.empty()) return;
  // Every leaf reference, the root's and the nodes' used slots, in one fixed order.
  std::vector<uint32_t*> leaves;
  if (BvhRef::is_leaf(root_)) leaves.push_back(&root_);
  for (BvhNode& node : nodes_)
    for (int slot = 0; slot < kBvhWidth; ++slot)
      if (node.bounds[0][slot] <= node.bounds[1][slot] && BvhRef::is_leaf(node.child[slot]))
        leaves.push_back(&node.child[slot]);
  // Which leaves become quad leaves (enough triangles and nothing else), and where their quads
  // start: a running sum in leaf order, so the array is the same whatever the thread count.
  std::vector<uint32_t> first_quad(leaves.size() + 1, 0);
  for (size_t k = 0; k < leaves.size(); ++k) {
    const uint32_t ref = *leaves[k];
    const uint32_t first = BvhRef::first(ref), count = BvhRef::count(ref);
    bool quads = count >= kMinQuadLeaf;
    for (uint32_t s = first; quads && s < first + count; ++s)
      quads = kind(slots_[s].id) == PrimitiveKind::kTriangle;  // shapes, instances and CSG keep their own tests
    first_quad[k + 1] = first_quad[k] + (quads ? BvhRef::quad_count(ref) : 0);
  }
  // Each quad written in full on the thread that fills its leaf (three cache lines a quad).
  quads_.resize(first_quad.back());
  parallel_for(leaves.size(), threads, 256, [&](unsigned, size_t k) {
    if (first_quad[k + 1] == first_quad[k]) return;
    const uint32_t ref = *leaves[k];
    const uint32_t first = BvhRef::first(ref), count = BvhRef::count(ref);
    uint32_t q = first_quad[k];
    for (uint32_t s = first; s < first + count; s += 4) {
      TriangleQuad quad{};  // zero edges in the lanes left over: never hit
      for (int lane = 0; lane < 4; ++lane) quad.id[lane] = ~0u;
      for (uint32_t lane = 0; lane < 4 && s + lane < first + count; ++lane)
        set_quad_lane(quad, static_cast<int>(lane), slots_[s + lane].triangle, slots_[s + lane].id);
      quads_[q++] = quad;
    }
  });
  for (size_t k = 0; k < leaves.size(); ++k)
    if (first_quad[k + 1] > first_quad[k]) *leaves[k] = BvhRef::quad_leaf(first_quad[k], BvhRef::count(*leaves[k]));
}

}  // namespace rt
