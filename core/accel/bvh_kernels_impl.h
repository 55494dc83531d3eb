// The one source of the BVH kernels (core/accel/bvh_kernels.h). A kernel file defines
// RTCLI_ISA_NS (its namespace), RTCLI_ISA (its Isa) and RTCLI_ISA_KERNEL, includes this, and
// is compiled with its instruction set's flags (core/CMakeLists.txt).
//
// The entry points are flattened: every inline function they call (the traversal, the triangle
// and quad tests, glm's maths) is compiled into them, so none is emitted out of line with this
// file's flags, where the linker could pick it for a baseline caller.
// tests/tools/check_kernel_symbols.cmake checks that with nm. What stays a call (the analytic shapes, CSG, libm) is
// baseline code.
#pragma once

#ifndef RTCLI_ISA_KERNEL
#error "define RTCLI_ISA_NS, RTCLI_ISA and RTCLI_ISA_KERNEL before including bvh_kernels_impl.h"
#endif

#include "core/accel/bvh_packet.h"
#include "core/accel/bvh_traversal.h"
#include "core/accel/shape_lanes.h"

namespace rt {
namespace RTCLI_ISA_NS {

bool intersect(const Bvh& bvh, Ray& ray, Hit& hit);

namespace {

// Takes `candidate` as the hit when it precedes it. r.tmax stays one float past the hit's t, so
// that a crossing at an equal t is still tested (every test accepts t < tmax only).
RT_SIMD_INLINE bool take_if_first(const Hit& candidate, Ray& r, Hit& hit) {
  if (!precedes(candidate, hit)) return false;
  hit = candidate;
  r.tmax = next_float_up(hit.t);
  return true;
}

// The crossings of a quad leaf's triangles that keep(id, b1, b2) accepts, merged into hit.
template <class Keep>
bool nearest_in_quads(const Bvh& bvh, uint32_t leaf, const QuadRay& quad_ray, Ray& r, Hit& hit, const Keep& keep) {
  bool found = false;
  const TriangleQuad* quads = bvh.quads().data() + BvhRef::first(leaf);
  for (uint32_t q = 0; q < BvhRef::quad_count(leaf); ++q) {
    Float4 t, b1, b2;
    for (unsigned mask = intersect_quad(quads[q], quad_ray, r.tmin, r.tmax, t, b1, b2); mask; mask &= mask - 1) {
      const Hit candidate = quad_lane_hit(quads[q], __builtin_ctz(mask), t, b1, b2);
      // The order first: keep() may read a texture.
      if (precedes(candidate, hit) && keep(candidate.prim, candidate.b1, candidate.b2))
        found |= take_if_first(candidate, r, hit);
    }
  }
  return found;
}

// The mesh's BVH in object space, its hit merged into `hit` (the triangle's index as part, `id`
// as prim).
bool intersect_instance(const MeshInstance& instance, uint32_t id, Ray& ray, Hit& hit);

// The closest crossing of slots [first, end) of a leaf that is not a quad leaf, merged into hit;
// primitive `skip` not tested (intersect_leaving; kNoPrimitive, a constant, folds the test away).
bool nearest_in_slots(const Bvh& bvh, uint32_t first, uint32_t end, Ray& r, Hit& hit, uint32_t skip = kNoPrimitive) {
  bool found = false;
  for (uint32_t slot = first; slot < end; ++slot) {
    const Bvh::Slot& s = bvh.slots()[slot];
    const uint32_t id = s.id;
    if (id == skip) continue;
    Hit candidate;
    bool got = false;
    switch (bvh.kind(id)) {
      case PrimitiveKind::kTriangle: got = intersect_triangle(s.triangle, r, candidate); break;
      case PrimitiveKind::kShape: got = intersect_shape(bvh.shape(id), r, candidate); break;
      case PrimitiveKind::kCsg: got = intersect_csg(bvh.csg(id), r, candidate); break;
      case PrimitiveKind::kInstance: found |= intersect_instance(bvh.instance(id), id, r, hit); continue;
    }
    candidate.prim = id;
    if (got) found |= take_if_first(candidate, r, hit);
  }
  return found;
}

// The closest crossing in a leaf merged into hit, as above: the one leaf test of intersect() and
// of the packets' walk.
bool nearest_in_leaf(const Bvh& bvh, uint32_t leaf, const QuadRay& quad_ray, Ray& r, Hit& hit,
                     uint32_t skip = kNoPrimitive) {
  if (BvhRef::is_quad_leaf(leaf))  // triangles only: never a shape to skip
    return nearest_in_quads(bvh, leaf, quad_ray, r, hit, [](uint32_t, float, float) { return true; });
  const uint32_t first = BvhRef::first(leaf);
  return nearest_in_slots(bvh, first, first + BvhRef::count(leaf), r, hit, skip);
}

}  // namespace

// The search's ray leaves with tmax at the hit (it ran one float past it).
RT_SIMD_INLINE void settle(Ray& ray, const Hit& hit, bool found) {
  if (found) ray.tmax = hit.t;
}

[[gnu::flatten]] bool intersect_cutout(const Bvh& bvh, Ray& ray, Hit& hit, const AlphaCutout& cutout) {
  bool found = false;
  const QuadRay quad_ray(ray);
  hit = Hit{};
  traverse<true>(bvh, ray, [&](uint32_t leaf, Ray& r) {
    if (BvhRef::is_quad_leaf(leaf)) {
      const auto kept = [&](uint32_t id, float b1, float b2) {
        return cutout.front_facing(id, r.direction) && cutout.covers(id, b1, b2, r);
      };
      found |= nearest_in_quads(bvh, leaf, quad_ray, r, hit, kept);
      return false;
    }
    const uint32_t first = BvhRef::first(leaf), end = first + BvhRef::count(leaf);
    for (uint32_t slot = first; slot < end; ++slot) {
      const Bvh::Slot& s = bvh.slots()[slot];
      Hit candidate;
      if (bvh.kind(s.id) == PrimitiveKind::kTriangle && intersect_triangle(s.triangle, r, candidate)) {
        candidate.prim = s.id;
        if (precedes(candidate, hit) && cutout.front_facing(s.id, r.direction) &&
            cutout.covers(s.id, candidate.b1, candidate.b2, r))
          found |= take_if_first(candidate, r, hit);
      }
    }
    return false;
  });
  settle(ray, hit, found);
  return found;
}

// The end of a closest-hit walk.
RT_SIMD_INLINE bool settle_nearest(const Bvh& bvh, Ray& ray, Hit& hit, bool found) {
  settle(ray, hit, found);
  // A flattened instance's triangle named as the instance's only now: the walk above ordered
  // equal hits by the tree's own ids, as the packets' walk does.
  if (found) bvh.relabel(hit);
  return found;
}

[[gnu::flatten]] bool intersect(const Bvh& bvh, Ray& ray, Hit& hit) {
  bool found = false;
  const QuadRay quad_ray(ray);
  hit = Hit{};
  traverse<true>(bvh, ray, [&](uint32_t leaf, Ray& r) {
    found |= nearest_in_leaf(bvh, leaf, quad_ray, r, hit);
    return false;
  });
  return settle_nearest(bvh, ray, hit, found);
}

// intersect() leaving primitive `from` untested (Bvh::intersect_leaving). A walk of its own: one
// walk shared with intersect() was emitted once, out of line, and called by both.
[[gnu::flatten]] bool intersect_leaving(const Bvh& bvh, Ray& ray, Hit& hit, uint32_t from) {
  bool found = false;
  const QuadRay quad_ray(ray);
  hit = Hit{};
  traverse<true>(bvh, ray, [&](uint32_t leaf, Ray& r) {
    found |= nearest_in_leaf(bvh, leaf, quad_ray, r, hit, from);
    return false;
  });
  return settle_nearest(bvh, ray, hit, found);
}

// Whether anything in a leaf crosses the ray: each primitive asked only whether it is crossed (a
// quad: whether any lane is), without making a hit record.
bool occluded(const Bvh& bvh, const Ray& ray);

namespace {

// Whether anything in slots [first, end) of a leaf that is not a quad leaf crosses the ray.
bool occluded_in_slots(const Bvh& bvh, uint32_t first, uint32_t end, const Ray& r) {
  for (uint32_t slot = first; slot < end; ++slot) {
    const Bvh::Slot& s = bvh.slots()[slot];
    Hit hit;
    Ray probe = r;
    switch (bvh.kind(s.id)) {
      case PrimitiveKind::kTriangle:
        if (intersect_triangle(s.triangle, probe, hit)) return true;
        break;
      case PrimitiveKind::kShape:
        if (intersect_shape(bvh.shape(s.id), probe, hit)) return true;
        break;
      case PrimitiveKind::kCsg:
        if (intersect_csg(bvh.csg(s.id), probe, hit)) return true;
        break;
      case PrimitiveKind::kInstance: {
        const MeshInstance& inst = bvh.instance(s.id);
        const Ray local = object_ray(inst.transform, r);
        if (!inst.cutout) {
          if (occluded(*inst.bvh, local)) return true;
          break;
        }
        // Behind an alpha mask: the first crossing the mask keeps (both faces block light).
        auto kept = [&](const Hit& h) { return inst.cutout->covers(h.prim, h.b1, h.b2, local); };
        if (for_each_primitive_hit(*inst.bvh, local, kept)) return true;
        break;
      }
    }
  }
  return false;
}

bool occluded_in_leaf(const Bvh& bvh, uint32_t leaf, const Ray& r, const QuadRay& quad_ray) {
  if (BvhRef::is_quad_leaf(leaf)) {
    const TriangleQuad* quads = bvh.quads().data() + BvhRef::first(leaf);
    for (uint32_t q = 0; q < BvhRef::quad_count(leaf); ++q) {
      Float4 t, b1, b2;
      if (intersect_quad(quads[q], quad_ray, r.tmin, r.tmax, t, b1, b2)) return true;
    }
    return false;
  }
  const uint32_t first = BvhRef::first(leaf);
  return occluded_in_slots(bvh, first, first + BvhRef::count(leaf), r);
}

#if defined(__AVX__)
// Fewer lanes than this in a leaf take its slots ray by ray, without the shapes' lanes
// (core/accel/shape_lanes.h): a lone ray is tested alone.
inline constexpr int kMinShapeLanes = 2;

// A leaf's occlusion answers for the packet's rays in `lanes` (bit i: rays[i] is blocked), each
// the single ray's (occluded_in_leaf). With enough lanes the slots are taken one at a time, an
// analytic shape's lanes first all at once (core/accel/shape_lanes.h).
unsigned blocked_in_leaf_packet(const Bvh& bvh, uint32_t leaf, unsigned lanes, LaneQuadRays& quad_rays, const Ray* rays,
                                LazyRayLanes& ray_lanes) {
  unsigned blocked = 0;
  if (BvhRef::is_quad_leaf(leaf) || __builtin_popcount(lanes) < kMinShapeLanes) {
    for (unsigned m = lanes; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      if (occluded_in_leaf(bvh, leaf, rays[i], quad_rays[i])) blocked |= 1u << i;
    }
    return blocked;
  }
  const uint32_t first = BvhRef::first(leaf), end = first + BvhRef::count(leaf);
  for (uint32_t slot = first; slot < end && blocked != lanes; ++slot) {
    const uint32_t id = bvh.slots()[slot].id;
    unsigned open = lanes & ~blocked;
    if (bvh.kind(id) == PrimitiveKind::kShape) {
      LaneCrossings crossings;
      unsigned unsure;
      blocked |= shape_hits(bvh.shape(id), ray_lanes.get(), open, crossings, unsure);
      open = unsure;
    }
    for (unsigned m = open; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      if (occluded_in_slots(bvh, slot, slot + 1, rays[i])) blocked |= 1u << i;
    }
  }
  return blocked;
}
#endif

}  // namespace

// Any hit, tuned: children in the order the node lists them, and the leaf test above. The same
// answer as for_each_hit with a visitor that stops at the first crossing (the bvh fuzzer checks).
[[gnu::flatten]] bool occluded(const Bvh& bvh, const Ray& ray) {
  Ray walk = ray;
  const QuadRay quad_ray(ray);
  return traverse<false>(bvh, walk,
                         [&](uint32_t leaf, const Ray& r) { return occluded_in_leaf(bvh, leaf, r, quad_ray); });
}

// Occlusion of up to kPacketSize rays (bit i: rays[i] is blocked), each the answer occluded()
// gives it. With AVX the rays walk the tree together (core/accel/bvh_packet.h); without it, one
// after another.
[[gnu::flatten]] unsigned occluded_packet(const Bvh& bvh, const Ray* rays, int count) {
#if defined(__AVX__)
  if (count > 1) {
    LazyRayLanes ray_lanes(rays, count);
    return occluded_packet_walk(bvh, rays, count, [&](uint32_t leaf, unsigned lanes, LaneQuadRays& quad_rays) {
      return blocked_in_leaf_packet(bvh, leaf, lanes, quad_rays, rays, ray_lanes);
    });
  }
#endif
  unsigned blocked = 0;
  for (int i = 0; i < count; ++i)
    if (occluded(bvh, rays[i])) blocked |= 1u << i;
  return blocked;
}

unsigned intersect_packet(const Bvh& bvh, Ray* rays, Hit* hits, int count);

namespace {

#if defined(__AVX__)
// Shape `id`'s crossings for the packet's rays in `lanes`, merged into their hits (found: bit i
// where rays[i]'s hit changed) where the lanes' test (core/accel/shape_lanes.h) knows the single
// ray's; returns the lanes still to be tested alone. Its t was found under the interval the leaf
// started with, which a nearer hit since may have cut short: the same crossing is the single
// ray's under the shorter one if it lies before its end, and none is if beyond. A float t equal
// to the end is left to the single-ray test, whose double t may lie on either side.
unsigned nearest_shape_packet(const Bvh& bvh, uint32_t id, unsigned lanes, Ray* rays, Hit* hits,
                              LazyRayLanes& ray_lanes, unsigned& found) {
  LaneCrossings c;
  unsigned unsure;
  const unsigned sure = shape_hits(bvh.shape(id), ray_lanes.get(), lanes, c, unsure);
  for (unsigned m = sure; m; m &= m - 1) {
    const int i = __builtin_ctz(m);
    if (c.t[i] == rays[i].tmax) {
      unsure |= 1u << i;
    } else if (c.t[i] < rays[i].tmax) {
      Hit candidate;
      candidate.t = c.t[i];
      candidate.prim = id;
      candidate.part = static_cast<uint32_t>(c.part[i]);
      if (take_if_first(candidate, rays[i], hits[i])) found |= 1u << i;
    }
  }
  return unsure;
}

// A leaf's nearest crossings for the packet's rays in `lanes`, merged into their hits. A mesh
// instance takes the rays on into its own BVH as a packet; an analytic shape is tested for all
// lanes at once first (nearest_shape_packet); everything else is the single-ray test, ray by ray.
// Flattened itself: it calls intersect_packet, so it is not inlined there.
[[gnu::flatten]] unsigned nearest_in_leaf_packet(const Bvh& bvh, uint32_t leaf, unsigned lanes, LaneQuadRays& quad_rays,
                                                 Ray* rays, Hit* hits, LazyRayLanes& ray_lanes) {
  unsigned found = 0;
  if (BvhRef::is_quad_leaf(leaf) || __builtin_popcount(lanes) < kMinPacket) {
    for (unsigned m = lanes; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      if (nearest_in_leaf(bvh, leaf, quad_rays[i], rays[i], hits[i])) found |= 1u << i;
    }
    return found;
  }
  const uint32_t first = BvhRef::first(leaf), end = first + BvhRef::count(leaf);
  for (uint32_t slot = first; slot < end; ++slot) {
    const uint32_t id = bvh.slots()[slot].id;
    if (bvh.kind(id) != PrimitiveKind::kInstance || bvh.instance(id).cutout) {
      unsigned open = lanes;
      if (bvh.kind(id) == PrimitiveKind::kShape)
        open = nearest_shape_packet(bvh, id, lanes, rays, hits, ray_lanes, found);
      for (unsigned m = open; m; m &= m - 1) {
        const int i = __builtin_ctz(m);
        if (nearest_in_slots(bvh, slot, slot + 1, rays[i], hits[i])) found |= 1u << i;
      }
      continue;
    }
    const MeshInstance& inst = bvh.instance(id);
    Ray local[kPacketSize];
    Hit local_hits[kPacketSize];
    int lane_of[kPacketSize];
    int n = 0;
    for (unsigned m = lanes; m; m &= m - 1, ++n) {
      lane_of[n] = __builtin_ctz(m);
      local[n] = object_ray(inst.transform, rays[lane_of[n]]);
    }
    for (unsigned m = intersect_packet(*inst.bvh, local, local_hits, n); m; m &= m - 1) {
      const int j = __builtin_ctz(m), i = lane_of[j];
      Hit h = local_hits[j];
      h.part = h.prim;
      h.prim = id;
      if (take_if_first(h, rays[i], hits[i])) found |= 1u << i;
    }
  }
  return found;
}
#endif

}  // namespace

// The closest hits of up to kPacketSize rays (bit i: rays[i] hit hits[i], and its tmax is
// narrowed to it), each what intersect() finds for it alone. With AVX and at least kMinPacket
// rays they walk the tree together (core/accel/bvh_packet.h); else one after another.
[[gnu::flatten]] unsigned intersect_packet(const Bvh& bvh, Ray* rays, Hit* hits, int count) {
  unsigned found = 0;
#if defined(__AVX__)
  if (count >= kMinPacket) {
    for (int i = 0; i < count; ++i) hits[i] = Hit{};
    LazyRayLanes ray_lanes(rays, count);
    intersect_packet_walk(bvh, rays, count, [&](uint32_t leaf, unsigned lanes, LaneQuadRays& quad_rays) {
      ray_lanes.narrow();
      found |= nearest_in_leaf_packet(bvh, leaf, lanes, quad_rays, rays, hits, ray_lanes);
    });
    for (unsigned m = found; m; m &= m - 1) {
      settle(rays[__builtin_ctz(m)], hits[__builtin_ctz(m)], true);
      bvh.relabel(hits[__builtin_ctz(m)]);
    }
    return found;
  }
#endif
  for (int i = 0; i < count; ++i)
    if (intersect(bvh, rays[i], hits[i])) found |= 1u << i;
  return found;
}

[[gnu::flatten]] bool visit_hits(const Bvh& bvh, const Ray& ray, HitVisitorFn visit, void* visitor) {
  auto call = [&](const Hit& hit) { return visit(visitor, hit); };
  return for_each_hit(bvh, ray, call);
}

// visit_hits' crossings for a ray that only `leaf` can meet: that leaf's, as the walk visits them.
[[gnu::flatten]] bool visit_hits_in_leaf(const Bvh& bvh, const Ray& ray, uint32_t leaf, HitVisitorFn visit,
                                         void* visitor) {
  if (bvh.primitive_count() == 0 || !is_traceable(ray)) return false;
  auto call = [&](const Hit& hit) { return visit(visitor, hit); };
  return visit_leaf_crossings(bvh, leaf, QuadRay(ray), ray, call);
}

namespace {

bool intersect_instance(const MeshInstance& instance, uint32_t id, Ray& ray, Hit& hit) {
  Ray local = object_ray(instance.transform, ray);
  Hit h;
  if (!(instance.cutout ? intersect_cutout(*instance.bvh, local, h, *instance.cutout)
                        : intersect(*instance.bvh, local, h)))
    return false;
  h.part = h.prim;
  h.prim = id;
  return take_if_first(h, ray, hit);
}

}  // namespace

extern const BvhKernels kKernels{RTCLI_ISA, &intersect,       &intersect_leaving, &intersect_cutout,  &intersect_packet,
                                 &occluded, &occluded_packet, &visit_hits,        &visit_hits_in_leaf};

}  // namespace RTCLI_ISA_NS
}  // namespace rt
