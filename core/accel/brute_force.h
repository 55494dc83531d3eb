// Tests every primitive. The reference the BVH is checked against; same interface as Bvh, and
// the same per-primitive crossing visitors (core/accel/primitives.h).
#pragma once

#include "core/accel/primitives.h"

namespace rt {

class BruteForce {
 public:
  explicit BruteForce(const PrimitiveSet& prims) : prims_(&prims) {}

  bool intersect(Ray& ray, Hit& hit) const {
    bool found = false;
    for (uint32_t id = 0; id < prims_->size(); ++id) found |= intersect_primitive(*prims_, id, ray, hit);
    return found;
  }
  bool occluded(const Ray& ray) const {
    return for_each_hit(ray, [](const Hit&) { return true; });
  }
  // As Bvh::for_each_hit: every crossing in the ray's interval, until visit returns true.
  template <class Visitor>
  bool for_each_hit(const Ray& ray, Visitor&& visit) const {
    for (uint32_t id = 0; id < prims_->size(); ++id) {
      bool stop = false;
      switch (prims_->kind(id)) {
        case PrimitiveKind::kTriangle: stop = visit_triangle_crossing(prims_->triangles[id], id, ray, visit); break;
        case PrimitiveKind::kShape: stop = visit_shape_crossings(prims_->shape(id), id, ray, visit); break;
        case PrimitiveKind::kCsg: stop = visit_csg_crossings(prims_->csg(id), id, ray, visit); break;
        case PrimitiveKind::kInstance: break;  // a reference set holds none
      }
      if (stop) return true;
    }
    return false;
  }

 private:
  const PrimitiveSet* prims_;
};

}  // namespace rt
