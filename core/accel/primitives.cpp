#include "core/accel/primitives.h"

namespace rt {
namespace {

void append_triangles(const TriangleMesh& m, std::vector<PackedTriangle>& out) {
  for (size_t i = 0; i + 2 < m.indices.size(); i += 3)
    out.push_back(PackedTriangle::from_vertices(m.positions[m.indices[i]], m.positions[m.indices[i + 1]],
                                                m.positions[m.indices[i + 2]]));
}

}  // namespace

PrimitiveSet make_triangle_set(const TriangleMesh& mesh) {
  PrimitiveSet prims;
  prims.triangles.reserve(mesh.triangle_count());
  append_triangles(mesh, prims.triangles);
  return prims;
}

PrimitiveSet make_primitive_set(const std::vector<TriangleMesh>& meshes, std::vector<AnalyticShape> shapes) {
  PrimitiveSet prims;
  size_t triangles = 0;
  for (const TriangleMesh& m : meshes) triangles += m.triangle_count();
  prims.triangles.reserve(triangles);
  for (const TriangleMesh& m : meshes) append_triangles(m, prims.triangles);
  prims.shapes = std::move(shapes);
  return prims;
}

}  // namespace rt
