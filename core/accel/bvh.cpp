// BVH traversal: the innermost loop of the renderer.
#include "core/accel/bvh.h"

namespace rt {
namespace {

// Slab test against the ray's current interval. The far distance is widened by a few ulps
// so that rounding never loses a box that the ray grazes (pbrt-v4's 1 + 2 * gamma(3)).
inline bool hits_box(const BvhNode& node, Vec3 origin, Vec3 inv_dir, float tmin, float tmax) {
  const Vec3 t0 = (node.lo - origin) * inv_dir;
  const Vec3 t1 = (node.hi - origin) * inv_dir;
  const Vec3 tnear = glm::min(t0, t1);
  const Vec3 tfar = glm::max(t0, t1);
  const float enter = std::max(std::max(tnear.x, tnear.y), std::max(tnear.z, tmin));
  const float leave = std::min(std::min(tfar.x, tfar.y), std::min(tfar.z, tmax)) * 1.0000004f;
  return enter <= leave;
}

}  // namespace

template <bool kAnyHit>
bool Bvh::traverse(Ray& ray, Hit& hit) const {
  if (nodes_.empty()) return false;
  const Vec3 inv_dir = 1.0f / ray.direction;
  const bool dir_negative[3] = {inv_dir.x < 0.0f, inv_dir.y < 0.0f, inv_dir.z < 0.0f};
  const auto triangle_count = static_cast<uint32_t>(prims_.triangles.size());
  uint32_t stack[kMaxDepth];
  int top = 0;
  uint32_t current = 0;
  bool found = false;
  for (;;) {
    const BvhNode& node = nodes_[current];
    if (hits_box(node, ray.origin, inv_dir, ray.tmin, ray.tmax)) {
      if (node.count == 0) {
        // Visit the child on the near side of the split plane first; the far one waits.
        if (dir_negative[node.axis]) {
          stack[top++] = current + 1;
          current = node.offset;
        } else {
          stack[top++] = node.offset;
          current = current + 1;
        }
        continue;
      }
      for (uint32_t slot = node.offset, end = node.offset + node.count; slot < end; ++slot) {
        const uint32_t id = order_[slot];
        const bool hit_now = id < triangle_count ? intersect_triangle(slot_triangles_[slot], ray, hit)
                                                 : intersect_shape(prims_.shape(id), ray, hit);
        if (hit_now) {
          if constexpr (kAnyHit) return true;
          hit.prim = id;
          ray.tmax = hit.t;
          found = true;
        }
      }
    }
    if (top == 0) break;
    current = stack[--top];
  }
  return found;
}

bool Bvh::intersect(Ray& ray, Hit& hit) const { return traverse<false>(ray, hit); }

bool Bvh::occluded(const Ray& ray) const {
  Ray r = ray;
  Hit h;
  return traverse<true>(r, h);
}

}  // namespace rt
