#include "core/scene.h"

#include <algorithm>

namespace rt {

SurfaceInteraction Scene::surface(const Ray& ray, const Hit& hit) const {
  if (!bvh.is_triangle(hit.prim)) return shape_surface(bvh.shape(hit.prim), ray, hit);
  // Meshes are few; a binary search over their first ids finds the owner of a triangle.
  const auto it = std::upper_bound(mesh_first_triangle.begin(), mesh_first_triangle.end(), hit.prim);
  const auto mesh = static_cast<size_t>(it - mesh_first_triangle.begin()) - 1;
  return mesh_surface(meshes[mesh], hit.prim - mesh_first_triangle[mesh], ray, hit);
}

}  // namespace rt
