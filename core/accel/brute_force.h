// Tests every primitive. The reference the BVH is checked against; same interface as Bvh.
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
    Ray r = ray;
    Hit h;
    for (uint32_t id = 0; id < prims_->size(); ++id)
      if (intersect_primitive(*prims_, id, r, h)) return true;
    return false;
  }

 private:
  const PrimitiveSet* prims_;
};

}  // namespace rt
