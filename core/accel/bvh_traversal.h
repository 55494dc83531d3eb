// BVH traversal, templated on what a leaf does: the closest-hit search, the any-hit test and
// every visitor of Bvh::for_each_hit share this one loop, and the compiler inlines each visitor
// into it (no virtual call, no function pointer per primitive). Included by the kernels of each
// instruction set (core/accel/bvh_kernels_impl.h) and by whoever calls for_each_hit.
//
// Everything here lives in namespace rt::RTCLI_ISA_NS: a kernel file names its instruction set
// before including this, every other file gets isa_generic. Code compiled for AVX2 then never
// shares a symbol with code compiled for the baseline.
#pragma once

#include <cstring>

#include "core/accel/bvh.h"
#include "core/simd.h"

#ifndef RTCLI_ISA_NS
#define RTCLI_ISA_NS isa_generic
#endif

namespace rt {
namespace RTCLI_ISA_NS {

// Each level pushes at most kBvhWidth - 1 entries; the tree is at most kMaxDepth deep.
constexpr int kStackSize = (kBvhWidth - 1) * Bvh::kMaxDepth + 4;

struct StackEntry {
  uint32_t ref;
  float t;  // where the ray enters the entry's box: skipped if a closer hit turns up meanwhile
};

static_assert(kBvhWidth == 8, "the slab test below is written for 8 lanes");

// A ray prepared for slab tests against a node's boxes at once. For each axis, the row of the
// node's bounds that the ray meets first (near) and last (far) follows from the direction sign,
// so an inverted (empty) box always yields near > far. With AVX one 8-lane vector holds a row;
// without it, two 4-lane halves (GCC splits an 8-lane vector for SSE badly: through memory).
struct RaySlabs {
#if defined(__AVX__)
  Float8 origin[3], inv_dir[3];
#else
  Float4 origin[3], inv_dir[3];
#endif
  int near_row[3], far_row[3];

  explicit RaySlabs(const Ray& ray) {
    for (int a = 0; a < 3; ++a) {
      const float inv = 1.0f / ray.direction[a];
#if defined(__AVX__)
      origin[a] = splat8(ray.origin[a]);
      inv_dir[a] = splat8(inv);
#else
      origin[a] = splat4(ray.origin[a]);
      inv_dir[a] = splat4(inv);
#endif
      near_row[a] = 2 * a + (inv < 0.0f ? 1 : 0);
      far_row[a] = 2 * a + (inv < 0.0f ? 0 : 1);
    }
  }

  // Bit i set when child i's box is entered within [tmin, tmax]; tnear[i] gets its entry distance.
  // The far distance is widened by a few ulps so rounding never loses a grazed box (pbrt-v4). A
  // slab that gives NaN (0 * inf: a direction component of 0, the origin on the box's plane)
  // constrains nothing: the running bound is the second operand, which min/max return when the
  // comparison is false, so [tmin, tmax] is never lost to a NaN.
  unsigned test(const BvhNode& node, float tmin, float tmax, float* tnear) const {
#if defined(__AVX__)
    Float8 lo = splat8(tmin), hi = splat8(tmax);
    for (int a = 0; a < 3; ++a) {
      lo = max8((load8(node.bounds[near_row[a]]) - origin[a]) * inv_dir[a], lo);
      hi = min8((load8(node.bounds[far_row[a]]) - origin[a]) * inv_dir[a], hi);
    }
    std::memcpy(tnear, &lo, sizeof lo);
    return movemask8(lo <= hi * splat8(1.0000004f));
#else
    unsigned mask = 0;
    for (int half = 0; half < kBvhWidth; half += 4) {
      Float4 lo = splat4(tmin), hi = splat4(tmax);
      for (int a = 0; a < 3; ++a) {
        lo = max4((load4(node.bounds[near_row[a]] + half) - origin[a]) * inv_dir[a], lo);
        hi = min4((load4(node.bounds[far_row[a]] + half) - origin[a]) * inv_dir[a], hi);
      }
      std::memcpy(tnear + half, &lo, sizeof lo);
      mask |= movemask4(lo <= hi * splat4(1.0000004f)) << half;
    }
    return mask;
#endif
  }
};

// Inserts e into stack[base, top), which is sorted by decreasing t.
inline void push_sorted(StackEntry* stack, int base, int& top, StackEntry e) {
  int i = top++;
  for (; i > base && stack[i - 1].t < e.t; --i) stack[i] = stack[i - 1];
  stack[i] = e;
}

// Asks the memory for what a child put on the closest-hit walk's stack holds (a node's cache
// lines, all of a quad leaf's quads: 1.04x on incoherent rays over its first quad alone) while
// the walk goes on with its nearer sibling: incoherent rays spend most of their time waiting for
// nodes and quads that are not in cache (the stone's incoherent rays 1.24x, camera rays 1.04x;
// docs/benchmark.md), and the packets' walks (core/accel/bvh_packet.h) for every child they enter
// (1.01-1.02x). The single ray's any-hit walk, which takes its children in no order, lost 3% with
// it and goes without (0.97-1.00x again with three-quad leaves).
RT_SIMD_INLINE void prefetch(const Bvh& bvh, uint32_t ref) {
  const char* p;
  int lines;
  if (!BvhRef::is_leaf(ref)) {
    p = reinterpret_cast<const char*>(bvh.nodes().data() + ref);
    lines = sizeof(BvhNode) / 64;
  } else if (BvhRef::is_quad_leaf(ref)) {
    p = reinterpret_cast<const char*>(bvh.quads().data() + BvhRef::first(ref));
    lines = static_cast<int>(BvhRef::quad_count(ref) * (sizeof(TriangleQuad) / 64));
  } else {
    return;
  }
  for (int l = 0; l < lines; ++l) __builtin_prefetch(p + 64 * l);
}

// Walks the boxes the ray enters and hands each leaf it reaches to visit_leaf(leaf_ref, ray)
// (a BvhRef: slots or quads), which returns true to stop. Returns whether a leaf stopped the walk.
// kNearestFirst (closest hit): children are taken nearest first, and a leaf may narrow ray.tmax
// so that boxes beyond it are skipped. Otherwise (any hit, every crossing) the order does not
// matter and is not paid for: the children entered are pushed as the node lists them.
template <bool kNearestFirst, class LeafVisitor>
bool traverse(const Bvh& bvh, Ray& ray, LeafVisitor&& visit_leaf) {
  if (bvh.primitive_count() == 0 || !is_traceable(ray)) return false;
  const BvhNode* nodes = bvh.nodes().data();
  const RaySlabs slabs(ray);
  StackEntry stack[kStackSize];
  int top = 0;
  stack[top++] = StackEntry{bvh.root(), ray.tmin};
  while (top > 0) {
    const StackEntry entry = stack[--top];
    // A closer hit found since the entry was pushed. (Any-hit never narrows tmax: no test, so
    // that a packet's walk, which has none, enters exactly the boxes a single ray enters.)
    if (kNearestFirst && entry.t > ray.tmax) continue;
    uint32_t ref = entry.ref;
    while (!BvhRef::is_leaf(ref)) {
      alignas(32) float t[kBvhWidth];
      const BvhNode& node = nodes[ref];
      // The child references' line, read after the slab test: asked for with the boxes' lines.
      __builtin_prefetch(node.child);
      unsigned mask = slabs.test(node, ray.tmin, ray.tmax, t);
      if (mask == 0) break;
      if constexpr (!kNearestFirst) {
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
        prefetch(bvh, node.child[far]);
        stack[top++] = StackEntry{node.child[far], t[far]};
        ref = node.child[near];
        continue;
      }
      // Three or more: insertion-sort them onto the stack by decreasing distance, pop the nearest
      // (asked for with the others: not worth a test).
      const int base = top;
      for (int s : {slot, other}) {
        prefetch(bvh, node.child[s]);
        push_sorted(stack, base, top, StackEntry{node.child[s], t[s]});
      }
      for (; mask; mask &= mask - 1) {
        const int s = __builtin_ctz(mask);
        prefetch(bvh, node.child[s]);
        push_sorted(stack, base, top, StackEntry{node.child[s], t[s]});
      }
      ref = stack[--top].ref;
    }
    if (!BvhRef::is_leaf(ref)) continue;  // the node's children were all missed
    if (visit_leaf(ref, ray)) return true;
  }
  return false;
}

// The crossings of a quad leaf (BvhRef::is_quad_leaf), in slot order.
template <class Visitor>
bool visit_quad_crossings(const Bvh& bvh, uint32_t leaf, const QuadRay& quad_ray, const Ray& ray, Visitor& visit) {
  const TriangleQuad* quads = bvh.quads().data() + BvhRef::first(leaf);
  for (uint32_t q = 0; q < BvhRef::quad_count(leaf); ++q) {
    Float4 t, b1, b2;
    for (unsigned mask = intersect_quad(quads[q], quad_ray, ray.tmin, ray.tmax, t, b1, b2); mask; mask &= mask - 1) {
      const Hit hit = quad_lane_hit(quads[q], __builtin_ctz(mask), t, b1, b2);
      if (visit(hit)) return true;
    }
  }
  return false;
}

// for_each_hit without the instance case: what an instance's (triangle-only) BVH runs, so that
// the visitor templates do not nest without end.
template <class Visitor>
bool for_each_primitive_hit(const Bvh& bvh, const Ray& ray, Visitor& visit) {
  Ray r = ray;  // never narrowed: every crossing in the interval is visited
  const QuadRay quad_ray(ray);
  return traverse<false>(bvh, r, [&](uint32_t leaf, const Ray& leaf_ray) {
    if (BvhRef::is_quad_leaf(leaf)) return visit_quad_crossings(bvh, leaf, quad_ray, leaf_ray, visit);
    const uint32_t first = BvhRef::first(leaf), end = first + BvhRef::count(leaf);
    for (uint32_t slot = first; slot < end; ++slot) {
      const Bvh::Slot& s = bvh.slots()[slot];
      // A BVH without instances or CSG solids (for_each_hit's shortcut, a mesh's own).
      const bool stop = bvh.kind(s.id) == PrimitiveKind::kTriangle
                            ? visit_triangle_crossing(s.triangle, s.id, leaf_ray, visit)
                            : visit_shape_crossings(bvh.shape(s.id), s.id, leaf_ray, visit);
      if (stop) return true;
    }
    return false;
  });
}

// The crossings of one leaf of a top-level BVH, in slot order, mesh instances' included
// (relabelled as the instance's: prim = instance id, part = triangle), until the visitor says stop.
template <class Visitor>
bool visit_leaf_crossings(const Bvh& bvh, uint32_t leaf, const QuadRay& quad_ray, const Ray& ray, Visitor& visit) {
  // A triangle's crossing as its flattened instance's (Bvh::relabel).
  auto own = [&](const Hit& h) {
    Hit g = h;
    bvh.relabel(g);
    return visit(static_cast<const Hit&>(g));
  };
  if (BvhRef::is_quad_leaf(leaf)) return visit_quad_crossings(bvh, leaf, quad_ray, ray, own);
  const uint32_t first = BvhRef::first(leaf), end = first + BvhRef::count(leaf);
  for (uint32_t slot = first; slot < end; ++slot) {
    const Bvh::Slot& s = bvh.slots()[slot];
    bool stop = false;
    switch (bvh.kind(s.id)) {
      case PrimitiveKind::kTriangle: stop = visit_triangle_crossing(s.triangle, s.id, ray, own); break;
      case PrimitiveKind::kShape: stop = visit_shape_crossings(bvh.shape(s.id), s.id, ray, visit); break;
      case PrimitiveKind::kCsg: stop = visit_csg_crossings(bvh.csg(s.id), s.id, ray, visit); break;
      case PrimitiveKind::kInstance: {
        const MeshInstance& inst = bvh.instance(s.id);
        const uint32_t id = s.id;
        const Ray local = object_ray(inst.transform, ray);
        auto relabel = [&](const Hit& h) {
          if (inst.cutout && !inst.cutout->covers(h.prim, h.b1, h.b2, local)) return false;  // cut out: go on
          Hit g = h;
          g.part = h.prim;
          g.prim = id;
          return visit(static_cast<const Hit&>(g));
        };
        stop = for_each_primitive_hit(*inst.bvh, local, relabel);
        break;
      }
    }
    if (stop) return true;
  }
  return false;
}

// Bvh::for_each_hit: every crossing, mesh instances' included, until the visitor says stop.
template <class Visitor>
bool for_each_hit(const Bvh& bvh, const Ray& ray, Visitor& visit) {
  if (bvh.instances().empty() && bvh.csgs().empty()) return for_each_primitive_hit(bvh, ray, visit);
  Ray r = ray;
  const QuadRay quad_ray(ray);
  return traverse<false>(bvh, r, [&](uint32_t leaf, const Ray& leaf_ray) {
    return visit_leaf_crossings(bvh, leaf, quad_ray, leaf_ray, visit);
  });
}

}  // namespace RTCLI_ISA_NS

// Not in the kernel files: they call their own namespace's functions, never this member, whose
// one definition must be the baseline's.
#ifndef RTCLI_ISA_KERNEL
template <class Visitor>
bool Bvh::for_each_hit(const Ray& ray, Visitor&& visit) const {
  return RTCLI_ISA_NS::for_each_hit(*this, ray, visit);
}
#endif

}  // namespace rt
