// Everything a ray can hit, addressed by one 32-bit id: triangles first, then analytic shapes,
// then mesh instances, then CSG solids. Dispatch is a switch on the id's kind (PrimitiveRanges,
// a few comparisons), not a virtual call. A mesh's own BVH holds only triangles; a scene's
// top-level BVH holds shapes, instances and CSG solids, and the world-space triangles of its
// flattened instances (core/flatten_instances.h), each owned by its instance.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/csg/csg_object.h"
#include "core/mesh.h"
#include "core/mesh_instance.h"
#include "core/shapes/analytic_shape.h"
#include "core/shapes/triangle.h"

namespace rt {

// The kinds of primitive, declared once; every leaf test switches on them.
enum class PrimitiveKind : uint8_t { kTriangle, kShape, kInstance, kCsg };

// Where each kind's ids begin: the one rule from an id to its kind, for PrimitiveSet and Bvh.
struct PrimitiveRanges {
  uint32_t shape_begin = 0, instance_begin = 0, csg_begin = 0, end = 0;

  PrimitiveKind kind(uint32_t id) const {
    if (id < shape_begin) return PrimitiveKind::kTriangle;
    if (id < instance_begin) return PrimitiveKind::kShape;
    return id < csg_begin ? PrimitiveKind::kInstance : PrimitiveKind::kCsg;
  }
};

// The instance a top-level triangle stands in for: its index in PrimitiveSet::instances and the
// triangle's index in the instance's mesh.
struct TriangleOwner {
  uint32_t instance = 0;
  uint32_t triangle = 0;
};

struct PrimitiveSet {
  std::vector<PackedTriangle> triangles;  // ids [0, triangles.size())
  // Empty, or one per triangle: whose it is, when the triangles are flattened instances' (a
  // top level's). A BVH names a hit on one as its instance's (Bvh::relabel).
  std::vector<TriangleOwner> owners;
  std::vector<AnalyticShape> shapes;    // then the shapes,
  std::vector<MeshInstance> instances;  // the instances,
  std::vector<CsgObject> csgs;          // and the CSG solids

  PrimitiveRanges ranges() const {
    const auto t = static_cast<uint32_t>(triangles.size()), s = static_cast<uint32_t>(shapes.size());
    const auto i = static_cast<uint32_t>(instances.size()), c = static_cast<uint32_t>(csgs.size());
    return PrimitiveRanges{t, t + s, t + s + i, t + s + i + c};
  }
  uint32_t size() const { return ranges().end; }
  PrimitiveKind kind(uint32_t id) const { return ranges().kind(id); }
  const AnalyticShape& shape(uint32_t id) const { return shapes[id - ranges().shape_begin]; }
  const MeshInstance& instance(uint32_t id) const { return instances[id - ranges().instance_begin]; }
  const CsgObject& csg(uint32_t id) const { return csgs[id - ranges().csg_begin]; }
  Aabb bounds(uint32_t id) const {
    switch (kind(id)) {
      case PrimitiveKind::kTriangle: return triangles[id].bounds();
      case PrimitiveKind::kShape: return world_bounds(shape(id));
      case PrimitiveKind::kInstance: return instance(id).bounds;
      case PrimitiveKind::kCsg: return csg(id).bounds();
    }
    return {};
  }
};

// The triangles of one mesh, in index order: what a mesh's own BVH is built over.
PrimitiveSet make_triangle_set(const TriangleMesh& mesh);
// Every triangle of the meshes (mesh by mesh, in index order), then the shapes.
PrimitiveSet make_primitive_set(const std::vector<TriangleMesh>& meshes, std::vector<AnalyticShape> shapes);

// Intersects triangle, shape or CSG solid `id` (not an instance: see Bvh); on a hit inside the
// ray's interval, fills `hit` and narrows ray.tmax.
inline bool intersect_primitive(const PrimitiveSet& prims, uint32_t id, Ray& ray, Hit& hit) {
  bool found = false;
  switch (prims.kind(id)) {
    case PrimitiveKind::kTriangle: found = intersect_triangle(prims.triangles[id], ray, hit); break;
    case PrimitiveKind::kShape: found = intersect_shape(prims.shape(id), ray, hit); break;
    case PrimitiveKind::kCsg: found = intersect_csg(prims.csg(id), ray, hit); break;
    case PrimitiveKind::kInstance: break;  // the Bvh's to walk
  }
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
