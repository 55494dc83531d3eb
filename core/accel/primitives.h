// Everything a ray can hit, addressed by one 32-bit id: triangles first, then analytic shapes.
// Dispatch is a comparison on the id, not a virtual call.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"
#include "core/shapes/analytic_shape.h"
#include "core/shapes/triangle.h"

namespace rt {

struct PrimitiveSet {
  std::vector<PackedTriangle> triangles;  // ids [0, triangles.size())
  std::vector<AnalyticShape> shapes;      // ids [triangles.size(), size())

  uint32_t size() const { return static_cast<uint32_t>(triangles.size() + shapes.size()); }
  bool is_triangle(uint32_t id) const { return id < triangles.size(); }
  const AnalyticShape& shape(uint32_t id) const { return shapes[id - triangles.size()]; }
  Aabb bounds(uint32_t id) const { return is_triangle(id) ? triangles[id].bounds() : world_bounds(shape(id)); }
};

// Every triangle of the meshes (mesh by mesh, in index order), then the shapes.
PrimitiveSet make_primitive_set(const std::vector<TriangleMesh>& meshes, std::vector<AnalyticShape> shapes);

// Intersects primitive `id`; on a hit inside the ray's interval, fills `hit` and narrows ray.tmax.
inline bool intersect_primitive(const PrimitiveSet& prims, uint32_t id, Ray& ray, Hit& hit) {
  const bool found = prims.is_triangle(id) ? intersect_triangle(prims.triangles[id], ray, hit)
                                           : intersect_shape(prims.shape(id), ray, hit);
  if (found) {
    hit.prim = id;
    ray.tmax = hit.t;
  }
  return found;
}

}  // namespace rt
