// BVH traversal, templated on what a leaf does: the closest-hit search, the any-hit test and
// every visitor of Bvh::for_each_hit share this one loop, and the compiler inlines each visitor
// into it (no virtual call, no function pointer per primitive). Included by bvh.cpp and by
// whoever calls for_each_hit.
#pragma once

#include <cstring>

#include "core/accel/bvh.h"
#include "core/accel/simd.h"

namespace rt {
namespace bvh_detail {

// Each 4-wide level pushes at most three entries; the tree is at most kMaxDepth deep.
constexpr int kStackSize = 3 * Bvh::kMaxDepth + 4;

struct StackEntry {
  uint32_t ref;
  float t;  // where the ray enters the entry's box: skipped if a closer hit turns up meanwhile
};

// A ray prepared for slab tests against four boxes at once. For each axis, the row of the
// node's bounds that the ray meets first (near) and last (far) follows from the direction sign,
// so an inverted (empty) box always yields near > far.
struct RaySlabs {
  Float4 origin[3], inv_dir[3];
  int near_row[3], far_row[3];

  explicit RaySlabs(const Ray& ray) {
    for (int a = 0; a < 3; ++a) {
      const float inv = 1.0f / ray.direction[a];
      origin[a] = splat4(ray.origin[a]);
      inv_dir[a] = splat4(inv);
      near_row[a] = 2 * a + (inv < 0.0f ? 1 : 0);
      far_row[a] = 2 * a + (inv < 0.0f ? 0 : 1);
    }
  }

  // Bit i set when child i's box is entered within [tmin, tmax]; tnear gets the entry distances.
  unsigned test(const BvhNode4& node, float tmin, float tmax, Float4& tnear) const {
    Float4 lo = splat4(tmin), hi = splat4(tmax);
    for (int a = 0; a < 3; ++a) {
      lo = max4(lo, (load4(node.bounds[near_row[a]]) - origin[a]) * inv_dir[a]);
      hi = min4(hi, (load4(node.bounds[far_row[a]]) - origin[a]) * inv_dir[a]);
    }
    tnear = lo;
    // Widen the far distance by a few ulps so rounding never loses a grazed box (pbrt-v4).
    return movemask4(lo <= hi * splat4(1.0000004f));
  }
};

// Inserts e into stack[base, top), which is sorted by decreasing t.
inline void push_sorted(StackEntry* stack, int base, int& top, StackEntry e) {
  int i = top++;
  for (; i > base && stack[i - 1].t < e.t; --i) stack[i] = stack[i - 1];
  stack[i] = e;
}

}  // namespace bvh_detail

// Walks the boxes the ray enters and hands each leaf it reaches to visit_leaf(first_slot,
// end_slot, ray), which returns true to stop. Returns whether a leaf stopped the walk.
// kNearestFirst (closest hit): children are taken nearest first, and a leaf may narrow ray.tmax
// so that boxes beyond it are skipped. Otherwise (any hit, every crossing) the order does not
// matter and is not paid for: the children entered are pushed as the node lists them.
template <bool kNearestFirst, class LeafVisitor>
bool Bvh::traverse(Ray& ray, LeafVisitor&& visit_leaf) const {
  using namespace bvh_detail;
  if (primitive_count() == 0) return false;
  const RaySlabs slabs(ray);
  StackEntry stack[kStackSize];
  int top = 0;
  stack[top++] = StackEntry{root_, ray.tmin};
  while (top > 0) {
    const StackEntry entry = stack[--top];
    if (entry.t > ray.tmax) continue;
    uint32_t ref = entry.ref;
    while (!BvhRef::is_leaf(ref)) {
      Float4 tnear;
      const BvhNode4& node = nodes_[ref];
      unsigned mask = slabs.test(node, ray.tmin, ray.tmax, tnear);
      if (mask == 0) break;
      if constexpr (!kNearestFirst) {
        alignas(16) float t[4];
        std::memcpy(t, &tnear, sizeof t);
        const int first = __builtin_ctz(mask);
        for (mask &= mask - 1; mask; mask &= mask - 1) {
          const int s = __builtin_ctz(mask);
          stack[top++] = StackEntry{node.child[s], t[s]};
        }
        ref = node.child[first];
        continue;
      }
      // Continue with the nearest child entered; push the others, farthest deepest, so that they
      // come off the stack nearest first. One or two hits are by far the common cases.
      alignas(16) float t[4];
      std::memcpy(t, &tnear, sizeof t);
      int slot = __builtin_ctz(mask);
      mask &= mask - 1;
      if (mask == 0) {
        ref = node.child[slot];
        continue;
      }
      const int other = __builtin_ctz(mask);
      mask &= mask - 1;
      if (mask == 0) {
        const bool first_nearer = t[slot] <= t[other];
        const int near = first_nearer ? slot : other, far = first_nearer ? other : slot;
        stack[top++] = StackEntry{node.child[far], t[far]};
        ref = node.child[near];
        continue;
      }
      // Three or four: insertion-sort them onto the stack by decreasing distance, pop the nearest.
      const int base = top;
      for (int s : {slot, other}) push_sorted(stack, base, top, StackEntry{node.child[s], t[s]});
      for (; mask; mask &= mask - 1) {
        const int s = __builtin_ctz(mask);
        push_sorted(stack, base, top, StackEntry{node.child[s], t[s]});
      }
      ref = stack[--top].ref;
    }
    if (!BvhRef::is_leaf(ref)) continue;  // the node's children were all missed
    if (visit_leaf(BvhRef::first(ref), BvhRef::first(ref) + BvhRef::count(ref), ray)) return true;
  }
  return false;
}

template <class Visitor>
bool Bvh::visit_quad_crossings(uint32_t first, uint32_t end, const QuadRay& quad_ray, const Ray& ray,
                               Visitor& visit) const {
  for (uint32_t q = leaf_quads_[first], slot = first; slot < end; ++q, slot += 4) {
    Float4 t, b1, b2;
    for (unsigned mask = intersect_quad(quads_[q], quad_ray, ray.tmin, ray.tmax, t, b1, b2); mask; mask &= mask - 1) {
      const int lane = __builtin_ctz(mask);
      Hit hit;
      hit.t = t[lane];
      hit.b1 = b1[lane];
      hit.b2 = b2[lane];
      hit.part = 0;
      hit.prim = slots_[slot + static_cast<uint32_t>(lane)].id;
      if (visit(static_cast<const Hit&>(hit))) return true;
    }
  }
  return false;
}

template <class Visitor>
bool Bvh::for_each_primitive_hit(const Ray& ray, Visitor& visit) const {
  Ray r = ray;  // never narrowed: every crossing in the interval is visited
  const QuadRay quad_ray(ray);
  return traverse<false>(r, [&](uint32_t first, uint32_t end, const Ray& leaf_ray) {
    if (leaf_quads_[first] != kNoQuads) return visit_quad_crossings(first, end, quad_ray, leaf_ray, visit);
    for (uint32_t slot = first; slot < end; ++slot) {
      const Slot& s = slots_[slot];
      const bool stop = s.id < triangle_count_ ? visit_triangle_crossing(s.triangle, s.id, leaf_ray, visit)
                                               : visit_shape_crossings(shape(s.id), s.id, leaf_ray, visit);
      if (stop) return true;
    }
    return false;
  });
}

template <class Visitor>
bool Bvh::for_each_hit(const Ray& ray, Visitor&& visit) const {
  if (instances_.empty() && csgs_.empty()) return for_each_primitive_hit(ray, visit);
  Ray r = ray;
  const QuadRay quad_ray(ray);
  return traverse<false>(r, [&](uint32_t first, uint32_t end, const Ray& leaf_ray) {
    if (leaf_quads_[first] != kNoQuads) return visit_quad_crossings(first, end, quad_ray, leaf_ray, visit);
    for (uint32_t slot = first; slot < end; ++slot) {
      const Slot& s = slots_[slot];
      bool stop = false;
      if (s.id < triangle_count_) {
        stop = visit_triangle_crossing(s.triangle, s.id, leaf_ray, visit);
      } else if (s.id < instance_begin()) {
        stop = visit_shape_crossings(shape(s.id), s.id, leaf_ray, visit);
      } else if (is_csg(s.id)) {
        stop = visit_csg_crossings(csg(s.id), s.id, leaf_ray, visit);
      } else {
        // The mesh's crossings, relabelled as the instance's: prim = instance id, part = triangle.
        const MeshInstance& inst = instance(s.id);
        const uint32_t id = s.id;
        auto relabel = [&](const Hit& h) {
          if (inst.cutout && !inst.cutout->covers(h.prim, h.b1, h.b2)) return false;  // cut out: go on
          Hit g = h;
          g.part = h.prim;
          g.prim = id;
          return visit(static_cast<const Hit&>(g));
        };
        stop = inst.bvh->for_each_primitive_hit(object_ray(inst.transform, leaf_ray), relabel);
      }
      if (stop) return true;
    }
    return false;
  });
}

}  // namespace rt
