// Bvh::build_quads: each leaf of three or more triangles alone copied into quads, four triangles a
// quad in slot order (the last one padded with lanes that are never hit), with their ids, and its
// reference turned into a quad leaf (BvhRef::quad_leaf). Traversal then tests the leaf's triangles
// four at a time (core/accel/triangle_quad.h) and finds exactly what the one-at-a-time loop would:
// the nearest, equals ordered by id (core/accel/bvh_kernels_impl.h, precedes).
#include "core/accel/bvh.h"

namespace rt {
namespace {

// Smaller leaves stay one triangle at a time: a quad is three cache lines, two triangles' slots
// fewer, and incoherent rays pay for every line they touch.
constexpr uint32_t kMinQuadLeaf = 3;

}  // namespace

void Bvh::build_quads() {
  const auto quad_ref = [&](uint32_t ref) {
    const uint32_t first = BvhRef::first(ref), count = BvhRef::count(ref);
    if (count < kMinQuadLeaf) return ref;
    for (uint32_t s = first; s < first + count; ++s)
      if (kind(slots_[s].id) != PrimitiveKind::kTriangle) return ref;  // shapes, instances and CSG keep their own tests
    const auto first_quad = static_cast<uint32_t>(quads_.size());
    for (uint32_t s = first; s < first + count; s += 4) {
      TriangleQuad quad{};  // zero edges in the lanes left over: never hit
      for (int lane = 0; lane < 4; ++lane) quad.id[lane] = ~0u;
      for (uint32_t lane = 0; lane < 4 && s + lane < first + count; ++lane)
        set_quad_lane(quad, static_cast<int>(lane), slots_[s + lane].triangle, slots_[s + lane].id);
      quads_.push_back(quad);
    }
    return BvhRef::quad_leaf(first_quad, count);
  };
  if (slots_.empty()) return;
  // Every leaf reference, the root's and the nodes' used slots.
  const auto each_leaf = [&](const auto& visit) {
    if (BvhRef::is_leaf(root_)) visit(root_);
    for (BvhNode& node : nodes_)
      for (int slot = 0; slot < kBvhWidth; ++slot)
        if (node.bounds[0][slot] <= node.bounds[1][slot] && BvhRef::is_leaf(node.child[slot])) visit(node.child[slot]);
  };
  // Room for every quad at once (an upper bound: a leaf takes ceil(count / 4)); quads are three
  // cache lines each, too many to copy on every regrowth.
  size_t quads = 0;
  each_leaf([&](uint32_t& ref) { quads += BvhRef::count(ref) >= kMinQuadLeaf ? BvhRef::quad_count(ref) : 0; });
  quads_.reserve(quads);
  each_leaf([&](uint32_t& ref) { ref = quad_ref(ref); });
}

}  // namespace rt
