#include "core/scene.h"

#include "core/storage_only.h"

namespace rt {

namespace {

SurfaceInteraction instance_surface(const SceneAssets& assets, const MeshInstance& instance, const Ray& ray,
                                    const Hit& hit) {
  SurfaceInteraction si = mesh_surface(assets.meshes[instance.mesh].mesh, hit.part, ray, hit, instance.transform);
  si.material = instance.material;
  return si;
}

}  // namespace

SurfaceInteraction Scene::other_surface(const Ray& ray, const Hit& hit, Texcoords texcoords) const {
  switch (bvh.kind(hit.prim)) {
    case PrimitiveKind::kInstance: return instance_surface(*assets, bvh.instance(hit.prim), ray, hit);
    case PrimitiveKind::kShape: return surface(ray, hit, texcoords);
    case PrimitiveKind::kCsg: {
      // The operand surface's own record, turned to face out of the solid.
      const CsgSurface& s = bvh.csg(hit.prim).surface(csg_surface_index(hit));
      SurfaceInteraction si = s.is_mesh
                                  ? instance_surface(*assets, s.mesh, ray, hit)
                                  : shape_surface(s.shape, ray, hit, reads_texcoords(s.shape.material, texcoords));
      orient_csg_surface(si, ray, hit);
      return si;
    }
    case PrimitiveKind::kTriangle: break;  // none: a flattened mesh's hits are named as its instance's
  }
  return SurfaceInteraction{};
}

namespace {

// The area lights' faces, each taking the ray's place as what it meets when nearer; a camera ray
// passes through those hidden from the camera.
void meet_area_lights(const Scene& scene, Ray& ray, SceneHit& out, bool camera_ray) {
  out.light = nullptr;
  for (const Light& light : scene.lights) {
    const RectLight* rect = std::get_if<RectLight>(&light);
    if (!rect || !(rect->camera_visible || !camera_ray)) continue;
    float t;
    Vec2 uv;  // written by a light the ray misses too: kept only for one it meets
    const auto l = static_cast<size_t>(&light - scene.lights.data());
    if (intersect_rect(*rect, scene.rect_frame(l), ray, t, &uv)) {  // nearer than the surface and the lights before
      ray.tmax = t;
      out.light = rect;
      out.light_uv = uv;
      out.surface = false;
    }
  }
}

}  // namespace

bool Scene::intersect(Ray& ray, SceneHit& out, RayStart from) const {
  out.surface = from.prim == kNoPrimitive ? bvh.intersect(ray, out.hit)
                : from.inwards            ? bvh.intersect_from_inside(from.prim, ray, out.hit)
                                          : bvh.intersect_leaving(from.prim, ray, out.hit);
  meet_area_lights(*this, ray, out, false);
  return out.surface || out.light;
}

void Scene::intersect_packet(Ray* rays, SceneHit* out, int count) const {
  StorageOnly<Hit, kPacketSize> storage;  // the walk starts each of the first count afresh
  Hit* hits = storage.at;
  const unsigned found = bvh.intersect_packet(rays, hits, count);
  for (int i = 0; i < count; ++i) {
    out[i].surface = (found >> i & 1u) != 0;
    out[i].hit = hits[i];
    meet_area_lights(*this, rays[i], out[i], true);
  }
}

uint32_t Scene::material_of(const Hit& hit) const {
  switch (bvh.kind(hit.prim)) {
    case PrimitiveKind::kInstance: return bvh.instance(hit.prim).material;
    case PrimitiveKind::kCsg: return bvh.csg(hit.prim).surface(csg_surface_index(hit)).material();
    case PrimitiveKind::kShape: return bvh.shape(hit.prim).material;
    case PrimitiveKind::kTriangle: break;  // none: a flattened mesh's hits are named as its instance's
  }
  return 0;
}

std::vector<TriangleMesh> Scene::world_meshes() const {
  std::vector<TriangleMesh> out;
  for (const MeshInstance& i : bvh.instances()) out.push_back(transformed(assets->meshes[i.mesh].mesh, i.transform));
  return out;
}

}  // namespace rt
