#include "core/scene.h"

#include <algorithm>

#include "core/accel/bvh_traversal.h"

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

Vec3 Scene::transmittance(const Ray& ray) const {
  Vec3 through(1.0f);
  // Optical depth, summed in any order: a crossing into an object at distance t adds -a t, one
  // out of it adds +a t, so a pair adds a (t_out - t_in), the length inside. Clamped at 0 for
  // the rare segment that ends inside glass (a light inside a block): that one counts as clear.
  Vec3 depth(0.0f);
  const float speed = glm::length(ray.direction);
  const bool blocked = bvh.for_each_hit(ray, [&](const Hit& hit) {
    const Material& m = materials[material_of(hit.prim)];
    if (!m.transmissive()) return true;
    through *= m.transmission;
    if (m.absorbing()) {
      const bool entering = surface(ray, hit).front_face;
      depth += (entering ? -hit.t : hit.t) * speed * m.absorption;
    }
    return max_component(through) <= 0.0f;
  });
  if (blocked) return Vec3(0.0f);
  return through * glm::exp(-glm::max(depth, Vec3(0.0f)));
}

}  // namespace rt
