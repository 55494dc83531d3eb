// Packets of up to eight rays walking the tree together, one ray per lane of an 8-lane vector:
// each node's child boxes are tested against all the packet's rays, and a child is entered with
// the lanes whose rays enter it. The node is read once for the packet, where eight single rays
// would read it up to eight times: the gain is for coherent rays (a point's shadow rays to an
// area light, neighbouring camera rays), whose walks share most nodes. Leaves are tested ray by
// ray, by the single-ray tests, so each ray gets exactly the answer it would get alone (for the
// closest hit, because equal distances are ordered by id, not by visiting order). AVX only (the
// SSE kernels loop over single rays: GCC lowers 8-lane vectors to SSE through memory).
#pragma once

#include <new>

#include "core/accel/bvh_traversal.h"
#include "core/accel/triangle_quad.h"

namespace rt {
namespace RTCLI_ISA_NS {

#if defined(__AVX__)

// Fewer rays than this walk one by one: a packet tests every child box for all eight lanes, which
// pays only when enough of them are in use (measured on camera rays: packets of 2 and 3 cost more
// than they saved).
inline constexpr int kMinPacket = 4;

// A packet's rays as rows of lanes, for slab tests of one child box against every ray at once.
// Spare lanes (count < 8) repeat ray 0; callers keep them masked off.
struct PacketSlabs {
  Float8 origin[3], inv[3];
  Mask8 positive[3];

  PacketSlabs(const Ray* rays, int count) {
    alignas(32) float lane[6][kPacketSize];  // origin xyz, 1/direction xyz
    for (int i = 0; i < kPacketSize; ++i) {
      const Ray& r = rays[i < count ? i : 0];
      for (int a = 0; a < 3; ++a) {
        lane[a][i] = r.origin[a];
        lane[3 + a][i] = 1.0f / r.direction[a];
      }
    }
    for (int a = 0; a < 3; ++a) {
      origin[a] = load8(lane[a]);
      inv[a] = load8(lane[3 + a]);
      positive[a] = inv[a] >= splat8(0.0f);
    }
  }

  // Each lane's entry distance into child c's box within [tmin, tmax]; bit i of `enter` set when
  // ray i enters it. Per lane, the near and far plane of each slab follow that ray's direction
  // sign, so an unused slot's inverted box (lo = +inf, hi = -inf) is never entered; the far
  // distance is widened as the single-ray test widens it (pbrt-v4).
  RT_SIMD_INLINE Float8 test(const BvhNode& node, int c, Float8 tmin, Float8 tmax, unsigned& enter) const {
    Float8 near = tmin, far = tmax;
    for (int a = 0; a < 3; ++a) {
      const Float8 lo = (splat8(node.bounds[2 * a][c]) - origin[a]) * inv[a];
      const Float8 hi = (splat8(node.bounds[2 * a + 1][c]) - origin[a]) * inv[a];
      near = max8(positive[a] ? lo : hi, near);  // NaN-proof as the single-ray test (RaySlabs)
      far = min8(positive[a] ? hi : lo, far);
    }
    enter = movemask8(near <= far * splat8(1.0000004f));
    return near;
  }
};

// One QuadRay per lane, built on the lane's first quad leaf (most packets meet none at the top
// level, where the leaves are shapes and instances).
class LaneQuadRays {
 public:
  explicit LaneQuadRays(const Ray* rays) : rays_(rays) {}
  const QuadRay& operator[](int i) {
    QuadRay* q = reinterpret_cast<QuadRay*>(storage_[i]);
    if (!(ready_ >> i & 1u)) {
      new (q) QuadRay(rays_[i]);
      ready_ |= 1u << i;
    }
    return *q;
  }

 private:
  const Ray* rays_;
  alignas(16) unsigned char storage_[kPacketSize][sizeof(QuadRay)];
  unsigned ready_ = 0;
};

// The lanes of rays a walk may take (is_traceable); the others miss, as they do alone.
RT_SIMD_INLINE unsigned traceable_lanes(const Ray* rays, int count) {
  unsigned lanes = 0;
  for (int i = 0; i < count; ++i) lanes |= static_cast<unsigned>(is_traceable(rays[i])) << i;
  return lanes;
}

// Calls blocked(leaf, i, quad_ray) for each leaf ray i, still unanswered, reaches; returns the
// mask of rays found blocked. Any-hit: the order of the walk does not matter.
template <class LeafTest>
unsigned occluded_packet_walk(const Bvh& bvh, const Ray* rays, int count, LeafTest&& blocked) {
  if (bvh.primitive_count() == 0) return 0;
  const PacketSlabs slabs(rays, count);
  alignas(32) float interval[2][kPacketSize];
  for (int i = 0; i < kPacketSize; ++i) {
    interval[0][i] = rays[i < count ? i : 0].tmin;
    interval[1][i] = rays[i < count ? i : 0].tmax;
  }
  const Float8 tmin = load8(interval[0]), tmax = load8(interval[1]);
  LaneQuadRays quad_rays(rays);

  struct Entry {
    uint32_t ref;
    unsigned lanes;
  };
  Entry stack[kBvhWidth * Bvh::kMaxDepth + 4];
  int top = 0;
  const unsigned all = traceable_lanes(rays, count);
  if (all == 0) return 0;
  unsigned done = 0;
  stack[top++] = Entry{bvh.root(), all};
  const BvhNode* nodes = bvh.nodes().data();
  while (top > 0) {
    const Entry e = stack[--top];
    const unsigned active = e.lanes & ~done;
    if (active == 0) continue;
    if (!BvhRef::is_leaf(e.ref)) {
      const BvhNode& node = nodes[e.ref];
      for (int c = 0; c < kBvhWidth; ++c) {
        unsigned enter;
        slabs.test(node, c, tmin, tmax, enter);
        enter &= active;
        if (!enter) continue;
        prefetch(bvh, node.child[c]);
        stack[top++] = Entry{node.child[c], enter};
      }
      continue;
    }
    for (unsigned m = active; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      if (blocked(e.ref, i, quad_rays[i])) done |= 1u << i;
    }
    if (done == all) break;
  }
  return done;
}

// Calls nearest(leaf, lanes, quad_rays) for each leaf that the rays in `lanes` may find a nearer
// hit in; it narrows those rays' tmax as it finds hits. Children are taken nearest first, by the
// entry distances of the packet's first ray still in them; an entry popped is left by the rays
// whose hit so far is nearer than its box.
template <class LeafNearest>
void intersect_packet_walk(const Bvh& bvh, Ray* rays, int count, LeafNearest&& nearest) {
  if (bvh.primitive_count() == 0) return;
  const PacketSlabs slabs(rays, count);
  alignas(32) float interval[2][kPacketSize];
  for (int i = 0; i < kPacketSize; ++i) {
    interval[0][i] = rays[i < count ? i : 0].tmin;
    interval[1][i] = rays[i < count ? i : 0].tmax;
  }
  const Float8 tmin = load8(interval[0]);
  Float8 tmax = load8(interval[1]);
  LaneQuadRays quad_rays(rays);

  struct Entry {
    Float8 near;  // each lane's entry distance into the box
    uint32_t ref;
    unsigned lanes;
  };
  Entry stack[kBvhWidth * Bvh::kMaxDepth + 4];
  int top = 0;
  const unsigned all = traceable_lanes(rays, count);
  if (all == 0) return;
  stack[top++] = Entry{tmin, bvh.root(), all};
  const BvhNode* nodes = bvh.nodes().data();
  while (top > 0) {
    const Entry& e = stack[--top];
    const unsigned active = e.lanes & movemask8(e.near <= tmax);
    if (active == 0) continue;
    const uint32_t ref = e.ref;
    if (!BvhRef::is_leaf(ref)) {
      const BvhNode& node = nodes[ref];
      const int lead = __builtin_ctz(active);  // whose distances order the children
      const int base = top;
      for (int c = 0; c < kBvhWidth; ++c) {
        unsigned enter;
        const Float8 near = slabs.test(node, c, tmin, tmax, enter);
        enter &= active;
        if (!enter) continue;
        prefetch(bvh, node.child[c]);
        // Insertion by decreasing distance, so that the nearest comes off the stack first.
        const Entry child{near, node.child[c], enter};
        int i = top++;
        for (; i > base && stack[i - 1].near[lead] < near[lead]; --i) stack[i] = stack[i - 1];
        stack[i] = child;
      }
      continue;
    }
    nearest(ref, active, quad_rays);
    for (unsigned m = active; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      interval[1][i] = rays[i].tmax;
    }
    tmax = load8(interval[1]);
  }
}

#endif

}  // namespace RTCLI_ISA_NS
}  // namespace rt
