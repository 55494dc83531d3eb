// A packet of up to eight rays walking the tree together, one ray per lane of an 8-lane vector:
// each node's child boxes are tested against all the packet's rays, and a child is entered with
// the lanes whose rays enter it. The node is read once for the packet, where eight single rays
// would read it up to eight times: the gain is for coherent rays (a point's shadow rays to an
// area light), whose walks share most nodes. Leaves are tested ray by ray, by the single-ray
// test, so each ray gets exactly the answer it would get alone. AVX only (the SSE kernels loop
// over single rays: GCC lowers 8-lane vectors to SSE through memory).
#pragma once

#include <new>

#include "core/accel/bvh_traversal.h"
#include "core/accel/triangle_quad.h"

namespace rt {
namespace RTCLI_ISA_NS {

#if defined(__AVX__)

// Calls blocked(leaf, ray, quad_ray) for each leaf a ray still unanswered reaches; returns the
// mask of rays found blocked. Any-hit: the order of the walk does not matter.
template <class LeafTest>
unsigned occluded_packet_walk(const Bvh& bvh, const Ray* rays, int count, LeafTest&& blocked) {
  if (bvh.primitive_count() == 0) return 0;
  alignas(32) float lane[8][kPacketSize];  // origin xyz, 1/direction xyz, tmin, tmax
  for (int i = 0; i < kPacketSize; ++i) {
    const Ray& r = rays[i < count ? i : 0];  // spare lanes repeat ray 0 and stay masked off
    for (int a = 0; a < 3; ++a) {
      lane[a][i] = r.origin[a];
      lane[3 + a][i] = 1.0f / r.direction[a];
    }
    lane[6][i] = r.tmin;
    lane[7][i] = r.tmax;
  }
  Float8 origin[3], inv[3];
  Mask8 positive[3];
  for (int a = 0; a < 3; ++a) {
    origin[a] = load8(lane[a]);
    inv[a] = load8(lane[3 + a]);
    positive[a] = inv[a] >= splat8(0.0f);
  }
  const Float8 tmin = load8(lane[6]), tmax = load8(lane[7]);
  alignas(16) unsigned char quad_storage[kPacketSize][sizeof(QuadRay)];  // built on a ray's first leaf
  unsigned quad_ready = 0;

  struct Entry {
    uint32_t ref;
    unsigned lanes;
  };
  Entry stack[kBvhWidth * Bvh::kMaxDepth + 4];
  int top = 0;
  const unsigned all = (1u << count) - 1u;
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
        // Per lane, the near and far plane of each slab follow that ray's direction sign, so an
        // unused slot's inverted box (lo = +inf, hi = -inf) is never entered.
        Float8 near = tmin, far = tmax;
        for (int a = 0; a < 3; ++a) {
          const Float8 lo = (splat8(node.bounds[2 * a][c]) - origin[a]) * inv[a];
          const Float8 hi = (splat8(node.bounds[2 * a + 1][c]) - origin[a]) * inv[a];
          near = max8(near, positive[a] ? lo : hi);
          far = min8(far, positive[a] ? hi : lo);
        }
        // The far distance widened as the single-ray test widens it (pbrt-v4).
        const unsigned enter = movemask8(near <= far * splat8(1.0000004f)) & active;
        if (enter) stack[top++] = Entry{node.child[c], enter};
      }
      continue;
    }
    for (unsigned m = active; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      QuadRay* quad_ray = reinterpret_cast<QuadRay*>(quad_storage[i]);
      if (!(quad_ready >> i & 1u)) {
        new (quad_ray) QuadRay(rays[i]);
        quad_ready |= 1u << i;
      }
      if (blocked(e.ref, rays[i], *quad_ray)) done |= 1u << i;
    }
    if (done == all) break;
  }
  return done;
}

#endif

}  // namespace RTCLI_ISA_NS
}  // namespace rt
