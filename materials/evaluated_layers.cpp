#include "materials/evaluated_layers.h"

#include "materials/slot_lookup.h"
#include "materials/surface_detail.h"

namespace rt {
namespace {

// A surface frame's tangent and handedness for a slot's mapping: the file's TANGENT where it
// has one, else dP/du of the mapping.
void tangent_frame(const TextureMapping& mapping, const SurfaceInteraction& si, Vec3 n, Vec3& tangent,
                   float& handedness) {
  if (si.tangent.w != 0.0f) {
    tangent = Vec3(si.tangent);
    handedness = si.tangent.w;
    return;
  }
  const MappedPoint p = map_point(mapping, si);
  tangent = p.dpdu;
  handedness = handedness_from_uv(n, p.dpdu, p.dpdv);
}

}  // namespace

EvaluatedLayers evaluate_layers(const PbrLayers& l, float reflect_ior, const SurfaceInteraction& si, Vec3 wo,
                                float side, const std::vector<Texture>& textures, float cone_width,
                                SurfaceDetailSwitches detail) {
  EvaluatedLayers e;
  const Vec3 d = -wo;
  const bool textured = detail.textures;
  const auto at = [&](const TextureSlot& slot) { return slot_at(slot, si, textures, d, cone_width, detail); };

  // Fresnel: ((ior - 1) / (ior + 1))^2 x colour, at most 1, x factor; F90 = factor.
  const float r = (reflect_ior - 1.0f) / (reflect_ior + 1.0f);
  const float f0 = reflect_ior == 1.5f ? 0.04f : r * r;  // exactly the core specification's 0.04
  Vec3 color = l.specular.color;
  float factor = l.specular.factor;
  if (textured && l.specular.color_texture.present()) color *= at(l.specular.color_texture);
  if (textured && l.specular.texture.present()) factor *= at(l.specular.texture).x;
  e.dielectric_f0 = glm::min(Vec3(f0) * color, Vec3(1.0f)) * factor;
  e.dielectric_f90 = factor;

  if (l.clearcoat.factor > 0.0f) {
    e.clearcoat = l.clearcoat.factor;
    e.clearcoat_roughness = l.clearcoat.roughness;
    if (textured && l.clearcoat.texture.present()) e.clearcoat *= at(l.clearcoat.texture).x;
    if (textured && l.clearcoat.roughness_texture.present())
      e.clearcoat_roughness *= at(l.clearcoat.roughness_texture).y;
    // The coat's normal: its own map over the geometry's normal, not the base's normal map.
    Vec3 n = si.shading_normal;
    if (detail.bumps && l.clearcoat.normal_map.map.present()) {
      const TextureSlot& map = l.clearcoat.normal_map.map;
      Vec3 tangent;
      float handedness;
      tangent_frame(map.mapping, si, n, tangent, handedness);
      n = tangent_space_normal(n, tangent, handedness, at(map), l.clearcoat.normal_map.scale);
    }
    n *= side;
    const float facing = glm::dot(n, wo);
    if (facing < 1e-3f) n = glm::normalize(n + (1e-3f - facing) * wo);
    e.clearcoat_n = n;
  }
  if (l.sheen.color != Vec3(0.0f)) {
    e.sheen_color = l.sheen.color;
    e.sheen_roughness = l.sheen.roughness;
    if (textured && l.sheen.color_texture.present()) e.sheen_color *= at(l.sheen.color_texture);
    if (textured && l.sheen.roughness_texture.present()) e.sheen_roughness *= at(l.sheen.roughness_texture).x;
  }
  if (l.anisotropy.strength > 0.0f) {
    Vec2 direction(1.0f, 0.0f);
    float strength = l.anisotropy.strength;
    if (textured && l.anisotropy.texture.present()) {
      const Vec3 t = at(l.anisotropy.texture);
      direction = Vec2(t.x, t.y) * 2.0f - Vec2(1.0f);
      strength *= t.z;
    }
    const float c = std::cos(l.anisotropy.rotation), s = std::sin(l.anisotropy.rotation);
    direction = Vec2(c * direction.x - s * direction.y, s * direction.x + c * direction.y);
    Vec3 tangent;
    float handedness;
    const TextureMapping mapping = l.anisotropy.texture.present() ? l.anisotropy.texture.mapping : TextureMapping{};
    tangent_frame(mapping, si, si.shading_normal, tangent, handedness);
    const Vec3 n = si.shading_normal;
    tangent = tangent - n * glm::dot(n, tangent);
    const float length2 = glm::dot(tangent, tangent);
    if (length2 > 1e-12f && glm::dot(direction, direction) > 1e-12f) {
      tangent /= std::sqrt(length2);
      const Vec3 bitangent = glm::cross(n, tangent) * handedness;
      e.anisotropy = std::clamp(strength, 0.0f, 1.0f);
      e.anisotropy_direction = glm::normalize(direction.x * tangent + direction.y * bitangent);
    }
  }
  if (l.iridescence.factor > 0.0f) {
    e.iridescence = l.iridescence.factor;
    e.iridescence_ior = l.iridescence.ior;
    e.iridescence_thickness = l.iridescence.thickness_max;
    if (textured && l.iridescence.texture.present()) e.iridescence *= at(l.iridescence.texture).x;
    if (textured && l.iridescence.thickness_texture.present())
      e.iridescence_thickness =
          l.iridescence.thickness_min +
          (l.iridescence.thickness_max - l.iridescence.thickness_min) * at(l.iridescence.thickness_texture).y;
  }
  e.dispersion = l.dispersion;
  return e;
}

}  // namespace rt
