// The one source of the BVH kernels (core/accel/bvh_kernels.h). A kernel file defines
// RTCLI_ISA_NS (its namespace), RTCLI_ISA (its Isa) and RTCLI_ISA_KERNEL, includes this, and
// is compiled with its instruction set's flags (core/CMakeLists.txt).
//
// The entry points are flattened: every inline function they call (the traversal, the triangle
// and quad tests, glm's maths) is compiled into them, so none is emitted out of line with this
// file's flags, where the linker could pick it for a baseline caller. tests/core/CMakeLists.txt
// checks that with nm. What stays a call (the analytic shapes, CSG, libm) is baseline code.
#pragma once

#ifndef RTCLI_ISA_KERNEL
#error "define RTCLI_ISA_NS, RTCLI_ISA and RTCLI_ISA_KERNEL before including bvh_kernels_impl.h"
#endif

#include "core/accel/bvh_traversal.h"

namespace rt {
namespace RTCLI_ISA_NS {

bool intersect(const Bvh& bvh, Ray& ray, Hit& hit);

namespace {

// The mesh's BVH in object space; the triangle's index goes to hit.part, the caller sets prim.
bool intersect_instance(const MeshInstance& instance, const Ray& ray, Hit& hit);

}  // namespace

[[gnu::flatten]] bool intersect_cutout(const Bvh& bvh, Ray& ray, Hit& hit, const AlphaCutout& cutout) {
  bool found = false;
  const QuadRay quad_ray(ray);
  traverse<true>(bvh, ray, [&](uint32_t first, uint32_t end, Ray& r) {
    if (const uint32_t q0 = bvh.leaf_quads()[first]; q0 != Bvh::kNoQuads) {
      // Four triangles at a time; of the lanes hit that the cutout keeps, the nearest (the first
      // of equals, as in slot order).
      for (uint32_t q = q0, slot = first; slot < end; ++q, slot += 4) {
        Float4 t, b1, b2;
        int best = -1;
        for (unsigned mask = intersect_quad(bvh.quads()[q], quad_ray, r.tmin, r.tmax, t, b1, b2); mask;
             mask &= mask - 1) {
          const int lane = __builtin_ctz(mask);
          const uint32_t id = bvh.slots()[slot + static_cast<uint32_t>(lane)].id;
          if ((best < 0 || t[lane] < t[best]) && cutout.front_facing(id, r.direction) &&
              cutout.covers(id, b1[lane], b2[lane]))
            best = lane;
        }
        if (best < 0) continue;
        hit.t = t[best];
        hit.b1 = b1[best];
        hit.b2 = b2[best];
        hit.part = 0;
        hit.prim = bvh.slots()[slot + static_cast<uint32_t>(best)].id;
        r.tmax = hit.t;
        found = true;
      }
      return false;
    }
    for (uint32_t slot = first; slot < end; ++slot) {
      const Bvh::Slot& s = bvh.slots()[slot];
      Hit candidate;
      if (s.id < bvh.triangle_count() && intersect_triangle(s.triangle, r, candidate) &&
          cutout.front_facing(s.id, r.direction) && cutout.covers(s.id, candidate.b1, candidate.b2)) {
        hit = candidate;
        hit.prim = s.id;
        r.tmax = hit.t;
        found = true;
      }
    }
    return false;
  });
  return found;
}

[[gnu::flatten]] bool intersect(const Bvh& bvh, Ray& ray, Hit& hit) {
  bool found = false;
  const QuadRay quad_ray(ray);
  traverse<true>(bvh, ray, [&](uint32_t first, uint32_t end, Ray& r) {
    if (const uint32_t q0 = bvh.leaf_quads()[first]; q0 != Bvh::kNoQuads) {
      // Four triangles at a time; the nearest lane wins, the first of equals (as in slot order).
      for (uint32_t q = q0, slot = first; slot < end; ++q, slot += 4) {
        Float4 t, b1, b2;
        unsigned mask = intersect_quad(bvh.quads()[q], quad_ray, r.tmin, r.tmax, t, b1, b2);
        if (!mask) continue;
        int best = __builtin_ctz(mask);
        for (mask &= mask - 1; mask; mask &= mask - 1) {
          const int lane = __builtin_ctz(mask);
          if (t[lane] < t[best]) best = lane;
        }
        hit.t = t[best];
        hit.b1 = b1[best];
        hit.b2 = b2[best];
        hit.part = 0;
        hit.prim = bvh.slots()[slot + static_cast<uint32_t>(best)].id;
        r.tmax = hit.t;
        found = true;
      }
      return false;
    }
    for (uint32_t slot = first; slot < end; ++slot) {
      const Bvh::Slot& s = bvh.slots()[slot];
      const uint32_t id = s.id;
      // Shapes before instances and CSG solids: a scene without CSG pays one comparison.
      const bool got = id < bvh.triangle_count()    ? intersect_triangle(s.triangle, r, hit)
                       : id < bvh.instance_begin() ? intersect_shape(bvh.shape(id), r, hit)
                       : id < bvh.csg_begin()      ? intersect_instance(bvh.instance(id), r, hit)
                                                   : intersect_csg(bvh.csg(id), r, hit);
      if (got) {
        hit.prim = id;
        r.tmax = hit.t;
        found = true;
      }
    }
    return false;
  });
  return found;
}

[[gnu::flatten]] bool occluded(const Bvh& bvh, const Ray& ray) {
  auto stop_at_first = [](const Hit&) { return true; };
  return for_each_hit(bvh, ray, stop_at_first);
}

[[gnu::flatten]] bool visit_hits(const Bvh& bvh, const Ray& ray, HitVisitorFn visit, void* visitor) {
  auto call = [&](const Hit& hit) { return visit(visitor, hit); };
  return for_each_hit(bvh, ray, call);
}

namespace {

bool intersect_instance(const MeshInstance& instance, const Ray& ray, Hit& hit) {
  Ray local = object_ray(instance.transform, ray);
  Hit h;
  if (!(instance.cutout ? intersect_cutout(*instance.bvh, local, h, *instance.cutout)
                        : intersect(*instance.bvh, local, h)))
    return false;
  hit = h;
  hit.part = h.prim;
  return true;
}

}  // namespace

extern const BvhKernels kKernels{RTCLI_ISA, &intersect, &intersect_cutout, &occluded, &visit_hits};

}  // namespace RTCLI_ISA_NS
}  // namespace rt
