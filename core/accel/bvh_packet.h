// Packets of up to eight rays walking the tree together, one ray per lane of an 8-lane vector:
// each node's child boxes are tested against all the packet's rays, and a child is entered with
// the lanes whose rays enter it. The node is read once for the packet, where eight single rays
// would read it up to eight times: the gain is for coherent rays (a point's shadow rays to an
// area light, neighbouring camera rays), whose walks share most nodes. Leaves are tested ray by
// ray, by the single-ray tests, but for analytic shapes, tested for all lanes at once by the same
// arithmetic (core/accel/shape_lanes.h); so each ray gets exactly the answer it would get alone
// (for the closest hit, because equal distances are ordered by id, not by visiting order). AVX
// only (the SSE kernels loop over single rays: GCC lowers 8-lane vectors to SSE through memory).
#pragma once

#include <limits>
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

// A packet's rays, spare lanes (count < 8) repeating ray 0. lanes(field) gathers one number of
// each ray into a vector's lanes in registers: the rays were just written a number at a time, and
// stored to an array and loaded as a vector they waited for each store (no store forwards to a
// wider load).
struct PacketRays {
  const Ray* ray[kPacketSize];

  PacketRays(const Ray* rays, int count) {
    for (int i = 0; i < kPacketSize; ++i) ray[i] = &rays[i < count ? i : 0];
  }
  template <class Field>
  RT_SIMD_INLINE Float8 lanes(Field field) const {
    return Float8{field(*ray[0]), field(*ray[1]), field(*ray[2]), field(*ray[3]),
                  field(*ray[4]), field(*ray[5]), field(*ray[6]), field(*ray[7])};
  }
};

// A packet's rays as rows of lanes, for slab tests of one child box against every ray at once.
// Spare lanes (count < 8) repeat ray 0; callers keep them masked off. The reciprocals are one
// vector division an axis (each lane's the correctly rounded 1/d, as a single ray's): eight rays'
// 24 scalar divisions were a sixth of a shadow packet's walk.
struct PacketSlabs {
  Float8 origin[3], inv[3];
  Mask8 positive[3];
  unsigned finite;  // bit i: ray i (i < count) has a finite origin and direction

  PacketSlabs(const Ray* rays, int count) {
    const PacketRays r(rays, count);
    const Float8 infinity = splat8(std::numeric_limits<float>::infinity());
    Mask8 is_finite = Mask8{} - 1;
    for (int a = 0; a < 3; ++a) {
      origin[a] = r.lanes([a](const Ray& ray) { return ray.origin[a]; });
      const Float8 direction = r.lanes([a](const Ray& ray) { return ray.direction[a]; });
      inv[a] = splat8(1.0f) / direction;
      positive[a] = inv[a] >= splat8(0.0f);
      is_finite &= (abs8(origin[a]) < infinity) & (abs8(direction) < infinity);  // NaN fails too
    }
    finite = movemask8(is_finite) & ((1u << count) - 1u);
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

// The lanes of rays a walk may take (is_traceable, lane by lane); the others miss, as they do
// alone.
RT_SIMD_INLINE unsigned traceable_lanes(const PacketSlabs& slabs, Float8 tmin, Float8 tmax) {
  return slabs.finite & movemask8(tmin <= tmax);
}

// Calls blocked(leaf, lanes, quad_rays) for each leaf that the rays in `lanes`, still unanswered,
// reach; it returns those it finds blocked, and the walk returns them all. Any-hit: the order of
// the walk does not matter.
template <class LeafTest>
unsigned occluded_packet_walk(const Bvh& bvh, const Ray* rays, int count, LeafTest&& blocked) {
  if (bvh.primitive_count() == 0) return 0;
  const PacketSlabs slabs(rays, count);
  const PacketRays packet(rays, count);
  const Float8 tmin = packet.lanes([](const Ray& r) { return r.tmin; });
  const Float8 tmax = packet.lanes([](const Ray& r) { return r.tmax; });
  LaneQuadRays quad_rays(rays);

  struct Entry {
    uint32_t ref;
    unsigned lanes;
  };
  Entry stack[kBvhWidth * Bvh::kMaxDepth + 4];
  int top = 0;
  const unsigned all = traceable_lanes(slabs, tmin, tmax);
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
    done |= blocked(e.ref, active, quad_rays);
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
  const PacketRays packet(rays, count);
  const auto ray_tmax = [](const Ray& r) { return r.tmax; };
  const Float8 tmin = packet.lanes([](const Ray& r) { return r.tmin; });
  Float8 tmax = packet.lanes(ray_tmax);
  LaneQuadRays quad_rays(rays);

  struct Entry {
    Float8 near;  // each lane's entry distance into the box
    uint32_t ref;
    unsigned lanes;
  };
  Entry stack[kBvhWidth * Bvh::kMaxDepth + 4];
  int top = 0;
  const unsigned all = traceable_lanes(slabs, tmin, tmax);
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
    tmax = packet.lanes(ray_tmax);
  }
}

#endif

}  // namespace RTCLI_ISA_NS
}  // namespace rt
