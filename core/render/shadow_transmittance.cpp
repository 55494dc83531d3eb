#include "core/render/shadow_transmittance.h"

#include "materials/evaluated_surface.h"
#include "materials/optics.h"

namespace rt {

Vec3 shadow_transmittance(const Scene& scene, const Ray& ray, const BvhLeafSet* among) {
  if (among && among->count == 0) return Vec3(1.0f);
  // The common case: every blocker is opaque, and the first one found ends the search.
  if (scene.all_opaque) return scene.occluded(ray) ? Vec3(0.0f) : Vec3(1.0f);
  Vec3 through(1.0f);
  // Optical depth, summed in any order: a crossing into an object at distance t adds -a t, one
  // out of it adds +a t, so a pair adds a (t_out - t_in), the length inside. Clamped at 0 for
  // the rare segment that ends inside glass (a light inside a block): that one counts as clear.
  Vec3 depth(0.0f);
  bool absorbed = false;
  auto visit = [&](const Hit& hit) {
    const Material& m = scene.materials()[scene.material_of(hit)];
    if (!m.transmissive()) return true;  // opaque: the common case, and the end of the search
    // What passes the interface: transmission times (1 - F0), the interface taken between the
    // material and air (shadow rays do not track nested media). Where a texture varies it (the
    // base colour, glTF's metallic or transmission map), the shading stage's value at the hit,
    // as the camera sees it; else the material's own.
    const bool textured =
        m.transmission_texture.present() || (m.pbr.enabled && (m.texture.present() || m.pbr.texture.present()));
    const SurfaceInteraction si = textured || m.absorbing() ? scene.surface(ray, hit) : SurfaceInteraction{};
    const Vec3 passed =
        textured ? evaluate_surface(m, si, ray.direction, scene.textures()).transmission : m.transmittance();
    through *= passed * (1.0f - schlick_reflectance(1.0f, 1.0f, m.ior));
    if (m.absorbing()) {  // (si: which way it crosses)
      depth += (si.front_face ? -hit.t : hit.t) * glm::length(ray.direction) * m.absorption;
      absorbed = true;
    }
    return max_component(through) <= 0.0f;
  };
  const bool blocked = among && among->count == 1 ? scene.bvh.visit_hits_in_leaf(ray, among->leaf[0], visit)
                                                  : scene.bvh.visit_hits(ray, visit);
  if (blocked) return Vec3(0.0f);
  return absorbed ? through * glm::exp(-glm::max(depth, Vec3(0.0f))) : through;
}

}  // namespace rt
