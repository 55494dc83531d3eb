#include "core/flatten_instances.h"

#include <algorithm>

#include "core/accel/bvh.h"

namespace rt {

void flatten_instances(PrimitiveSet& top, const std::vector<MeshGeometry>& meshes, size_t budget) {
  // Loose triangles of the set's own would have no owner to line up with.
  if (top.owners.size() != top.triangles.size()) return;
  size_t left = budget - std::min(budget, top.triangles.size());
  std::vector<uint32_t> placements(meshes.size(), 0);
  for (const MeshInstance& instance : top.instances)
    if (instance.mesh < meshes.size()) ++placements[instance.mesh];
  for (size_t k = 0; k < top.instances.size(); ++k) {
    MeshInstance& instance = top.instances[k];
    if (instance.flattened || instance.cutout || instance.mesh >= meshes.size() || placements[instance.mesh] != 1)
      continue;
    const MeshGeometry& geometry = meshes[instance.mesh];
    const TriangleMesh& mesh = geometry.mesh;
    const size_t count = mesh.triangle_count();
    // The mesh's BVH is over the same triangles, ids = their indices: the hits keep their names.
    if (geometry.bvh.primitive_count() != count || count > left) continue;
    // Appended in place; taken back if an edge overflows in the world.
    const size_t first = top.triangles.size();
    bool finite = true;
    for (size_t t = 0; t < count && finite; ++t) {
      const uint32_t* v = &mesh.indices[3 * t];
      top.triangles.push_back(PackedTriangle::from_vertices(instance.transform.point_to_world(mesh.positions[v[0]]),
                                                            instance.transform.point_to_world(mesh.positions[v[1]]),
                                                            instance.transform.point_to_world(mesh.positions[v[2]])));
      finite = top.triangles.back().is_finite();
    }
    if (!finite) {
      top.triangles.resize(first);
      continue;
    }
    for (size_t t = 0; t < count; ++t)
      top.owners.push_back(TriangleOwner{static_cast<uint32_t>(k), static_cast<uint32_t>(t)});
    instance.flattened = true;
    left -= count;
  }
}

}  // namespace rt
