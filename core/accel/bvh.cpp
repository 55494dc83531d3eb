// Closest-hit and any-hit queries: instances of the traversal in bvh_traversal.h.
#include "core/accel/bvh_traversal.h"

namespace rt {

namespace {

// The mesh's BVH in object space; the triangle's index goes to hit.part, the caller sets prim.
bool intersect_instance(const MeshInstance& instance, const Ray& ray, Hit& hit) {
  Ray local = object_ray(instance.transform, ray);
  Hit h;
  if (!(instance.cutout ? instance.bvh->intersect(local, h, *instance.cutout) : instance.bvh->intersect(local, h)))
    return false;
  hit = h;
  hit.part = h.prim;
  return true;
}

}  // namespace

bool Bvh::intersect(Ray& ray, Hit& hit) const {
  bool found = false;
  const QuadRay quad_ray(ray);
  traverse<true>(ray, [&](uint32_t first, uint32_t end, Ray& r) {
    if (const uint32_t q0 = leaf_quads_[first]; q0 != kNoQuads) {
      // Four triangles at a time; the nearest lane wins, the first of equals (as in slot order).
      for (uint32_t q = q0, slot = first; slot < end; ++q, slot += 4) {
        Float4 t, b1, b2;
        unsigned mask = intersect_quad(quads_[q], quad_ray, r.tmin, r.tmax, t, b1, b2);
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
        hit.prim = slots_[slot + static_cast<uint32_t>(best)].id;
        r.tmax = hit.t;
        found = true;
      }
      return false;
    }
    for (uint32_t slot = first; slot < end; ++slot) {
      const Slot& s = slots_[slot];
      const uint32_t id = s.id;
      // Shapes before instances and CSG solids: a scene without CSG pays one comparison.
      const bool got = id < triangle_count_    ? intersect_triangle(s.triangle, r, hit)
                       : id < instance_begin() ? intersect_shape(shape(id), r, hit)
                       : id < csg_begin()      ? intersect_instance(instance(id), r, hit)
                                               : intersect_csg(csg(id), r, hit);
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

bool Bvh::intersect(Ray& ray, Hit& hit, const AlphaCutout& cutout) const {
  bool found = false;
  traverse<true>(ray, [&](uint32_t first, uint32_t end, Ray& r) {
    for (uint32_t slot = first; slot < end; ++slot) {
      const Slot& s = slots_[slot];
      Hit candidate;
      if (s.id < triangle_count_ && intersect_triangle(s.triangle, r, candidate) &&
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

bool Bvh::occluded(const Ray& ray) const {
  return for_each_hit(ray, [](const Hit&) { return true; });
}

MeshInstance place_mesh(const Bvh& mesh_bvh, const Transform& transform, uint32_t mesh, uint32_t material,
                        const AlphaCutout* cutout) {
  return MeshInstance{&mesh_bvh, transform, transform_bounds(transform.to_world, mesh_bvh.bounds()),
                      mesh,      material,  cutout};
}

}  // namespace rt
