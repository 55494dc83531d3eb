// Everything a ray can hit, addressed by one 32-bit id: triangles first, then analytic shapes,
// then mesh instances, then CSG solids. Dispatch is a comparison on the id, not a virtual call. A mesh's own BVH
// holds only triangles; a scene's top-level BVH holds shapes and instances.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/mesh_instance.h"
#include "core/csg/csg_object.h"
#include "core/mesh.h"
#include "core/shapes/analytic_shape.h"
#include "core/shapes/triangle.h"

namespace rt {

struct PrimitiveSet {
  std::vector<PackedTriangle> triangles;  // ids [0, triangles.size())
  std::vector<AnalyticShape> shapes;      // ids [triangles.size(), shape_end())
  std::vector<MeshInstance> instances;    // ids [shape_end(), instance_end())
  std::vector<CsgObject> csgs;            // ids [instance_end(), size())

  uint32_t shape_end() const { return static_cast<uint32_t>(triangles.size() + shapes.size()); }
  uint32_t instance_end() const { return shape_end() + static_cast<uint32_t>(instances.size()); }
  uint32_t size() const { return instance_end() + static_cast<uint32_t>(csgs.size()); }
  bool is_triangle(uint32_t id) const { return id < triangles.size(); }
  bool is_instance(uint32_t id) const { return id >= shape_end() && id < instance_end(); }
  bool is_csg(uint32_t id) const { return id >= instance_end(); }
  const AnalyticShape& shape(uint32_t id) const { return shapes[id - triangles.size()]; }
  const MeshInstance& instance(uint32_t id) const { return instances[id - shape_end()]; }
  const CsgObject& csg(uint32_t id) const { return csgs[id - instance_end()]; }
  Aabb bounds(uint32_t id) const {
    return is_triangle(id)   ? triangles[id].bounds()
           : is_instance(id) ? instance(id).bounds
           : is_csg(id)      ? csg(id).bounds()
                             : world_bounds(shape(id));
  }
};

// The triangles of one mesh, in index order: what a mesh's own BVH is built over.
PrimitiveSet make_triangle_set(const TriangleMesh& mesh);
// Every triangle of the meshes (mesh by mesh, in index order), then the shapes.
PrimitiveSet make_primitive_set(const std::vector<TriangleMesh>& meshes, std::vector<AnalyticShape> shapes);

// Intersects triangle, shape or CSG solid `id` (not an instance: see Bvh); on a hit inside the
// ray's interval, fills `hit` and narrows ray.tmax.
inline bool intersect_primitive(const PrimitiveSet& prims, uint32_t id, Ray& ray, Hit& hit) {
  const bool found = prims.is_triangle(id) ? intersect_triangle(prims.triangles[id], ray, hit)
                     : prims.is_csg(id)    ? intersect_csg(prims.csg(id), ray, hit)
                                           : intersect_shape(prims.shape(id), ray, hit);
  if (found) {
    hit.prim = id;
    ray.tmax = hit.t;
  }
  return found;
}

// Crossings of one primitive, for visitors that see every hit along a ray (shadow rays through
// glass, CSG's closed mesh operands). A triangle is crossed at most once; a convex analytic
// shape at most twice (the plane once). The loop re-intersects past the last crossing, so it
// needs no "all roots" routine per shape; the cap only guards against rounding surprises.
inline constexpr int kMaxShapeCrossings = 4;

// Calls visit(hit) for the crossing of triangle `id` in (ray.tmin, ray.tmax), with hit.prim set.
// Returns true when the visitor asked to stop.
template <class Visitor>
bool visit_triangle_crossing(const PackedTriangle& triangle, uint32_t id, const Ray& ray, Visitor& visit) {
  Hit hit;
  if (!intersect_triangle(triangle, ray, hit)) return false;
  hit.prim = id;
  return visit(static_cast<const Hit&>(hit));
}

// Calls visit(hit) for each crossing of shape `id` in (ray.tmin, ray.tmax), nearest first.
template <class Visitor>
bool visit_shape_crossings(const AnalyticShape& shape, uint32_t id, const Ray& ray, Visitor& visit) {
  Ray rest = ray;
  Hit hit;
  for (int i = 0; i < kMaxShapeCrossings && intersect_shape(shape, rest, hit); ++i) {
    hit.prim = id;
    if (visit(static_cast<const Hit&>(hit))) return true;
    // Past this crossing: the routines find roots in double and round them to float, so
    // tmin = hit.t could still let the same root through again.
    rest.tmin = std::nextafter(hit.t, kInfinity);
  }
  return false;
}

}  // namespace rt
