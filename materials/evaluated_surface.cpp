#include "materials/evaluated_surface.h"

#include "materials/evaluated_layers.h"
#include "materials/map_point.h"
#include "materials/pbr_to_phong.h"
#include "materials/slot_lookup.h"
#include "materials/surface_detail.h"

namespace rt {
namespace {

// The outward shading normal after the material's normal map, then its bump map.
Vec3 detailed_normal(const Material& m, const SurfaceInteraction& si, Vec3 direction,
                     const std::vector<Texture>& textures, float cone_width, SurfaceDetailSwitches detail) {
  Vec3 n = si.shading_normal;
  if (m.normal_map.map.present()) {
    const MappedPoint p = map_point(m.normal_map.map.mapping, si);
    const Vec3 texel = slot_sample(m.normal_map.map, textures, p.uv, uv_footprint(p, n, direction, cone_width), detail);
    // The file's own tangents (glTF TANGENT) belong to its first texture coordinates, unmoved.
    const TextureMapping& mapping = m.normal_map.map.mapping;
    const bool file_tangents = si.tangent.w != 0.0f && mapping.projection == Projection::kUv && mapping.uv_set == 0 &&
                               mapping.scale == Vec2(1.0f) && mapping.rotation_degrees == 0.0f;
    n = file_tangents
            ? tangent_space_normal(n, Vec3(si.tangent), si.tangent.w, texel, m.normal_map.scale)
            : tangent_space_normal(n, p.dpdu, handedness_from_uv(n, p.dpdu, p.dpdv), texel, m.normal_map.scale);
  }
  if (m.bump.height.present()) {
    SurfaceInteraction tilted = si;
    tilted.shading_normal = n;
    const MappedPoint p = map_point(m.bump.height.mapping, tilted);
    const Vec2 h = height_gradient(m.bump, textures, p.uv, uv_footprint(p, n, direction, cone_width),
                                   detail.override_filter ? detail.filter : m.bump.height.mapping.filter);
    n = blinn_bump(n, p.dpdu, p.dpdv, h.x, h.y);
  }
  return n;
}

// The emission factor times its texture (before an unlit material's colour).
Vec3 own_emission(const Material& m, const SurfaceInteraction& si, const std::vector<Texture>& textures, Vec3 direction,
                  float cone_width, SurfaceDetailSwitches detail) {
  Vec3 e = m.emission;
  if (m.emission_texture.present() && detail.textures && e != Vec3(0.0f))
    e *= slot_at(m.emission_texture, si, textures, direction, cone_width, detail);
  return e;
}

// The diffuse (or base) colour: the factor, times the colour texture, times COLOR_0.
Vec3 base_color_at(const Material& m, const SurfaceInteraction& si, const std::vector<Texture>& textures,
                   Vec3 direction, float cone_width, SurfaceDetailSwitches detail) {
  Vec3 kd = m.kd * Vec3(si.color);
  if (detail.textures && m.texture.present()) kd *= slot_at(m.texture, si, textures, direction, cone_width, detail);
  return kd;
}

}  // namespace

Vec3 emitted_radiance(const Material& m, const SurfaceInteraction& si, Vec3 ray_direction,
                      const std::vector<Texture>& textures, float cone_width, SurfaceDetailSwitches detail) {
  const Vec3 direction = glm::normalize(ray_direction);
  Vec3 e = own_emission(m, si, textures, direction, cone_width, detail);
  if (m.unlit) e += base_color_at(m, si, textures, direction, cone_width, detail);
  return e;
}

EvaluatedSurface evaluate_mapped_surface(const Material& m, const SurfaceInteraction& si, Vec3 unit_direction,
                                         const std::vector<Texture>& textures, float cone_width,
                                         SurfaceDetailSwitches detail) {
  // Worked out in locals and written once, at the end (evaluated_surface): a surface made first
  // and filled in was zeroed whole before the calls below, which kept the compiler from seeing
  // that the stores after them make the zeros dead.
  const Vec3 wo = -unit_direction;
  // Shade the side the ray sees: both sides of an opaque surface are lit like its front.
  const float side = si.front_face ? 1.0f : -1.0f;
  const bool detailed = detail.bumps && (m.normal_map.map.present() || m.bump.height.present());
  Vec3 n = side * (detailed ? detailed_normal(m, si, unit_direction, textures, cone_width, detail) : si.shading_normal);
  // A tilted normal can turn away from the viewer near a silhouette, where Phong would go black:
  // bend it back just past the edge of visibility.
  if (detailed) {
    const float facing = glm::dot(n, wo);
    if (facing < 1e-3f) n = glm::normalize(n + (1e-3f - facing) * wo);
  }
  const Vec3 kd = base_color_at(m, si, textures, unit_direction, cone_width, detail);
  Vec3 transmission = m.transmission;
  if (detail.textures && m.transmission_texture.present() && m.transmissive())
    transmission *= slot_at(m.transmission_texture, si, textures, unit_direction, cone_width, detail).x;
  PhongTerms phong;  // the Phong terms: the material's, or glTF's model converted
  float transmission_factor = 0.0f, refraction_glossy = 0.0f;
  float metallic = 0.0f, roughness = 1.0f;
  EvaluatedLayers layers;
  if (m.pbr.enabled) {  // glTF's model, converted here so that its texture can vary it
    float metallic_factor = m.pbr.metallic, roughness_factor = m.pbr.roughness;
    if (detail.textures && m.pbr.texture.present()) {
      const Vec3 t = slot_at(m.pbr.texture, si, textures, unit_direction, cone_width, detail);
      roughness_factor *= t.y;
      metallic_factor *= t.z;
    }
    metallic = std::clamp(metallic_factor, 0.0f, 1.0f);
    roughness = std::clamp(roughness_factor, 0.0f, 1.0f);
    // BLEND's see-through index 1 is not the surface's: it reflects as the core model's 1.5.
    const float reflect_ior = m.transmission_is_coverage && m.ior == 1.0f ? 1.5f : m.ior;
    layers = evaluate_layers(m.pbr.layers, reflect_ior, si, wo, side, textures, cone_width, detail);
    phong = layers.any_layer() || !layers.default_fresnel()
                ? pbr_to_phong(kd, metallic_factor, roughness_factor, layers, glm::dot(n, wo))
                : pbr_to_phong(kd, metallic_factor, roughness_factor);
    // KHR_materials_transmission: metal lets nothing through; what passes is tinted by the base
    // colour and blurred by the roughness (Whitted: refracted rays spread like glossy ones).
    // (BLEND's transmission is coverage: what the surface does not cover passes untinted.)
    if (!m.transmission_is_coverage) transmission *= 1.0f - metallic;
    transmission_factor = max_component(transmission);
    phong.kd *= Vec3(1.0f) - transmission;
    if (!m.transmission_is_coverage) transmission *= kd;
    refraction_glossy = transmission_factor > 0.0f && !m.transmission_is_coverage ? phong.glossy : 0.0f;
  } else {
    transmission_factor = max_component(transmission);
    phong.kd = kd * (Vec3(1.0f) - transmission);
    phong.ks = m.ks;
    if (detail.textures && m.specular_texture.present())
      phong.ks *= slot_at(m.specular_texture, si, textures, unit_direction, cone_width, detail);
    phong.shininess = m.shininess;
    phong.reflectivity = m.reflectivity;
    phong.glossy = m.glossy;
  }
  Vec3 emission = own_emission(m, si, textures, unit_direction, cone_width, detail);
  if (m.unlit) {  // shown as it is: nothing reflected, scattered or passed on
    emission += kd;
    phong.kd = phong.ks = phong.reflectivity = transmission = Vec3(0.0f);
    transmission_factor = 0.0f;
  }
  return evaluated_surface(
      m, si, wo, side,
      MaterialTerms{.n = n,
                    .phong = phong,
                    .transmission = transmission,
                    .transmission_factor = transmission_factor,
                    .refraction_glossy = refraction_glossy,
                    .emission = emission,
                    .pbr = m.pbr.enabled && !m.unlit
                               ? std::optional(PbrSurfaceTerms{
                                     .base_color = kd, .metallic = metallic, .roughness = roughness, .layers = layers})
                               : std::nullopt});
}

}  // namespace rt
