// One immutable, render-ready frame: the camera, the lights and the top-level BVH that places
// shapes, CSG solids and the shared meshes where they are at this moment. io builds it (for an animation,
// core/scene_graph.h builds one per frame); the renderer and every thread only read it.
#pragma once

#include <memory>
#include <vector>

#include "core/accel/bvh.h"
#include "core/camera.h"
#include "core/lights/emitters.h"
#include "core/lights/environment.h"
#include "core/lights/light.h"
#include "core/lights/light_selection.h"
#include "core/scene_assets.h"

namespace rt {

// Where a ray starts, when the integrator knows: on primitive `prim`, into it (a refraction
// entering it, a reflection on its inside) or out of it. Scene::intersect walks less for it.
struct RayStart {
  uint32_t prim = kNoPrimitive;
  bool inwards = false;
};

// What a ray meets first: a surface in the BVH, or the face of an area light. Area lights are
// not in the BVH (they cast no shadow: shadow rays ask occluded()), but a camera, mirror or glossy
// ray that meets one before any surface sees it. The scene finds them, so that no integrator
// needs a loop of its own (as pbrt's, Mitsuba's and Tungsten's emitters).
struct SceneHit {
  bool surface = false;
  Hit hit;                           // when surface: the BVH's record, for Scene::surface()
  const RectLight* light = nullptr;  // else, when the ray met an area light's face
  Vec2 light_uv{0.0f};               // where on it: along edge1 and edge2, each in [0, 1]
};

struct Scene {
  std::shared_ptr<const SceneAssets> assets = std::make_shared<const SceneAssets>();
  Camera camera;
  Environment background;  // radiance of rays that meet nothing: a colour or an HDR image
  Vec3 ambient{0.0f};      // ambient light, multiplied by each material's kd
  std::vector<Light> lights;
  Bvh bvh;  // top level: analytic shapes, mesh instances (each pointing into assets->meshes), CSG solids
  // No material lets light through: a shadow ray needs only bvh.occluded(), the early-out
  // occlusion kernel, not the transmittance visitor. False (the visitor, always right) unless
  // whoever builds the scene has checked.
  bool all_opaque = false;
  // The emissive mesh triangles, for the path tracer's light sampling (empty unless whoever
  // builds the scene makes it: SceneGraph::at does).
  Emitters emitters;
  // Which light the path tracer samples where there are many (core/lights/light_selection.h).
  LightSelection light_selection;
  // Per material: whether its shading reads texture coordinates (Material::reads_texcoords). A
  // sphere's (u, v) frame, atan2, acos and three sines, is not made for one that does not (5% of
  // refraction.json's render, measured). Empty: every material does, the safe default.
  std::vector<uint8_t> texcoords_read;
  // Per material: whether it is a uniform Phong material (Material::uniform_phong), whose shading
  // record the Whitted integrator makes inline (uniform_phong_surface): one byte read a hit, not the
  // material's eight texture and model fields (refraction.json 0.5% fewer instructions). Empty:
  // none is, the safe default (the general evaluation, evaluate_mapped_surface, for all).
  std::vector<uint8_t> uniform_phong;
  // Per light: a rect light's frame (normal, area), which every light sample reads; worked out
  // once here rather than per sample (a cross product, two square roots and a division: 1.5% of
  // the path-traced Cornell box, measured). Empty: worked out when asked, the safe default.
  std::vector<RectFrame> rect_frames;

  // The frame of light l, a rect light.
  RectFrame rect_frame(size_t l) const {
    return l < rect_frames.size() ? rect_frames[l] : RectFrame(std::get<RectLight>(lights[l]));
  }

  const std::vector<Material>& materials() const { return assets->materials; }
  const std::vector<Texture>& textures() const { return assets->textures; }

  // The closest surface (ray.tmax becomes its distance); area lights are not surfaces.
  bool intersect(Ray& ray, Hit& hit) const { return bvh.intersect(ray, hit); }
  // The closest surface or area light's face; ray.tmax becomes its distance. False: nothing.
  // `from`: where the ray starts, if known. Into a primitive, a hint that never changes the
  // answer (Bvh::intersect_from_inside); out of one, a promise that it is outwards
  // (Bvh::intersect_leaving).
  bool intersect(Ray& ray, SceneHit& out, RayStart from = {}) const;
  // intersect(ray, out) for count <= kPacketSize camera rays (neighbours), their surfaces found
  // together (Bvh::intersect_packet): each gets what it would get alone, but passes through the
  // area lights hidden from the camera (RectLight::camera_visible).
  void intersect_packet(Ray* rays, SceneHit* out, int count) const;
  bool occluded(const Ray& ray) const { return bvh.occluded(ray); }
  unsigned occluded_packet(const Ray* rays, int count) const { return bvh.occluded_packet(rays, count); }
  bool is_uniform_phong(uint32_t material) const {
    return material < uniform_phong.size() && uniform_phong[material] != 0;
  }
  // The material index at a hit of the top-level BVH (a CSG solid's differs by operand).
  uint32_t material_of(const Hit& hit) const;

  // The full surface record of a hit returned by intersect(); its texture coordinates where the
  // material reads them (kAsRead: for shading) or always (kAlways: to show them).
  enum class Texcoords { kAsRead, kAlways };
  // An analytic shape's, the common case, made here: inline, a hit's surface costs one call, not
  // two (refraction.json 1% fewer instructions). Meshes and CSG solids: other_surface().
  SurfaceInteraction surface(const Ray& ray, const Hit& hit, Texcoords texcoords = Texcoords::kAsRead) const {
    if (bvh.kind(hit.prim) != PrimitiveKind::kShape) return other_surface(ray, hit, texcoords);
    const AnalyticShape& shape = bvh.shape(hit.prim);
    return shape_surface(shape, ray, hit, reads_texcoords(shape.material, texcoords));
  }

  // Every placed mesh copied into world space, in instance order: for one-level reference
  // structures (tests, the ray benchmark), not for rendering.
  std::vector<TriangleMesh> world_meshes() const;

 private:
  bool reads_texcoords(uint32_t material, Texcoords texcoords) const {
    return texcoords == Texcoords::kAlways || material >= texcoords_read.size() || texcoords_read[material] != 0;
  }
  SurfaceInteraction other_surface(const Ray& ray, const Hit& hit, Texcoords texcoords) const;
};

}  // namespace rt
