#include "core/scene.h"

namespace rt {

SurfaceInteraction Scene::surface(const Ray& ray, const Hit& hit) const {
  if (!bvh.is_instance(hit.prim)) return shape_surface(bvh.shape(hit.prim), ray, hit);
  const MeshInstance& instance = bvh.instance(hit.prim);
  SurfaceInteraction si = mesh_surface(assets->meshes[instance.mesh].mesh, hit.part, ray, hit, instance.transform);
  si.material = instance.material;
  return si;
}

bool Scene::intersect(Ray& ray, SceneHit& out) const {
  out.surface = bvh.intersect(ray, out.hit);
  out.light = nullptr;
  for (const Light& light : lights) {
    const RectLight* rect = std::get_if<RectLight>(&light);
    float t;
    if (rect && rect->intersect(ray, t, &out.light_uv)) {  // nearer than the surface and the lights before
      ray.tmax = t;
      out.light = rect;
      out.surface = false;
    }
  }
  return out.surface || out.light;
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
