// Closest-hit and any-hit queries: instances of the traversal in bvh_traversal.h.
#include "core/accel/bvh_traversal.h"

namespace rt {

bool Bvh::intersect(Ray& ray, Hit& hit) const {
  bool found = false;
  traverse(ray, [&](uint32_t first, uint32_t end, Ray& r) {
    for (uint32_t slot = first; slot < end; ++slot) {
      const Slot& s = slots_[slot];
      const uint32_t id = s.id;
      if (id < triangle_count_ ? intersect_triangle(s.triangle, r, hit) : intersect_shape(shape(id), r, hit)) {
        hit.prim = id;
        r.tmax = hit.t;
        found = true;
      }
    }
    return false;
  });
  return found;
}

bool Bvh::occluded(const Ray& ray) const {
  return for_each_hit(ray, [](const Hit&) { return true; });
}

}  // namespace rt
