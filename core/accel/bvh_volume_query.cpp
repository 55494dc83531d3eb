// Bvh::leaves_meeting: the leaves a volume reaches, found by walking the boxes it meets.
#include "core/accel/bvh.h"

namespace rt {
namespace {

// Whether a leaf holds something a ray inside the volume may cross: anything but planes it
// passes beside (a quad leaf's triangles always count).
bool leaf_reachable(const Bvh& bvh, uint32_t leaf, const ShadowVolume& volume) {
  if (BvhRef::is_quad_leaf(leaf)) return true;
  const uint32_t first = BvhRef::first(leaf), end = first + BvhRef::count(leaf);
  for (uint32_t slot = first; slot < end; ++slot) {
    const uint32_t id = bvh.slots()[slot].id;
    if (bvh.kind(id) != PrimitiveKind::kShape || bvh.shape(id).kind != ShapeKind::kPlane) return true;
    if (!volume.beside_plane(bvh.shape(id).transform)) return true;
  }
  return false;
}

}  // namespace

bool Bvh::leaves_meeting(const ShadowVolume& volume, BvhLeafSet& out) const {
  out.count = 0;
  // A full set ends the walk (the caller then traces as usual), so a volume over a large mesh
  // costs a few nodes, not the tree.
  return for_each_leaf_meeting([&](const Aabb& box) { return volume.meets(box); },
                               [&](uint32_t leaf) {
                                 if (!leaf_reachable(*this, leaf, volume)) return true;
                                 if (out.count == BvhLeafSet::kMax) return false;
                                 out.leaf[out.count++] = leaf;
                                 return true;
                               });
}

}  // namespace rt
