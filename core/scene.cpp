#include "core/scene.h"

#include <algorithm>

namespace rt {
namespace {

// Meshes are few; a binary search over their first primitive ids finds a triangle's owner.
size_t mesh_of(const std::vector<uint32_t>& first_triangle, uint32_t prim) {
  const auto it = std::upper_bound(first_triangle.begin(), first_triangle.end(), prim);
  return static_cast<size_t>(it - first_triangle.begin()) - 1;
}

}  // namespace

SurfaceInteraction Scene::surface(const Ray& ray, const Hit& hit) const {
  if (!bvh.is_triangle(hit.prim)) return shape_surface(bvh.shape(hit.prim), ray, hit);
  const size_t mesh = mesh_of(mesh_first_triangle, hit.prim);
  return mesh_surface(meshes[mesh], hit.prim - mesh_first_triangle[mesh], ray, hit);
}

uint32_t Scene::material_of(uint32_t prim) const {
  if (!bvh.is_triangle(prim)) return bvh.shape(prim).material;
  return meshes[mesh_of(mesh_first_triangle, prim)].material;
}

}  // namespace rt
