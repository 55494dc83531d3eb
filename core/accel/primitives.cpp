#include "core/accel/primitives.h"

namespace rt {

PrimitiveSet make_primitive_set(const std::vector<TriangleMesh>& meshes, std::vector<AnalyticShape> shapes) {
  PrimitiveSet prims;
  size_t triangles = 0;
  for (const TriangleMesh& m : meshes) triangles += m.triangle_count();
  prims.triangles.reserve(triangles);
  for (const TriangleMesh& m : meshes)
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3)
      prims.triangles.push_back(PackedTriangle::from_vertices(m.positions[m.indices[i]], m.positions[m.indices[i + 1]],
                                                              m.positions[m.indices[i + 2]]));
  prims.shapes = std::move(shapes);
  return prims;
}

}  // namespace rt
