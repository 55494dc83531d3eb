#include "core/scene.h"

namespace rt {

SurfaceInteraction Scene::surface(const Ray& ray, const Hit& hit) const {
  if (!bvh.is_instance(hit.prim)) return shape_surface(bvh.shape(hit.prim), ray, hit);
  const MeshInstance& instance = bvh.instance(hit.prim);
  SurfaceInteraction si = mesh_surface(assets->meshes[instance.mesh].mesh, hit.part, ray, hit, instance.transform);
  si.material = instance.material;
  return si;
}

uint32_t Scene::material_of(uint32_t prim) const {
  return bvh.is_instance(prim) ? bvh.instance(prim).material : bvh.shape(prim).material;
}

std::vector<TriangleMesh> Scene::world_meshes() const {
  std::vector<TriangleMesh> out;
  for (const MeshInstance& i : bvh.instances()) out.push_back(transformed(assets->meshes[i.mesh].mesh, i.transform));
  return out;
}

}  // namespace rt
