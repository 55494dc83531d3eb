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

EvaluatedSurface evaluate_surface_unit(const Material& m, const SurfaceInteraction& si, Vec3 unit_direction,
                                       const std::vector<Texture>& textures, float cone_width,
                                       SurfaceDetailSwitches detail) {
  EvaluatedSurface s;
  s.position = si.position;
  s.position_error = si.position_error;
  s.shadow_lift = si.shadow_lift;
  s.wo = -unit_direction;
  // Shade the side the ray sees: both sides of an opaque surface are lit like its front.
  const float side = si.front_face ? 1.0f : -1.0f;
  s.ng = side * si.geometric_normal;
  const bool detailed = detail.bumps && (m.normal_map.map.present() || m.bump.height.present());
  s.n = side * (detailed ? detailed_normal(m, si, -s.wo, textures, cone_width, detail) : si.shading_normal);
  // A tilted normal can turn away from the viewer near a silhouette, where Phong would go black:
  // bend it back just past the edge of visibility.
  if (detailed) {
    const float facing = glm::dot(s.n, s.wo);
    if (facing < 1e-3f) s.n = glm::normalize(s.n + (1e-3f - facing) * s.wo);
  }
  s.entering = si.front_face;
  s.material = si.material;
  s.medium = si.medium == kOwnMedium ? si.material : si.medium;
  const Vec3 kd = base_color_at(m, si, textures, -s.wo, cone_width, detail);
  Vec3 transmission = m.transmission;
  if (detail.textures && m.transmission_texture.present() && m.transmissive())
    transmission *= slot_at(m.transmission_texture, si, textures, -s.wo, cone_width, detail).x;
  if (m.pbr.enabled) {  // glTF's model, converted here so that its texture can vary it
    float metallic = m.pbr.metallic, roughness = m.pbr.roughness;
    if (detail.textures && m.pbr.texture.present()) {
      const Vec3 t = slot_at(m.pbr.texture, si, textures, -s.wo, cone_width, detail);
      roughness *= t.y;
      metallic *= t.z;
    }
    s.pbr = true;
    s.base_color = kd;
    s.metallic = std::clamp(metallic, 0.0f, 1.0f);
    s.roughness = std::clamp(roughness, 0.0f, 1.0f);
    // BLEND's see-through index 1 is not the surface's: it reflects as the core model's 1.5.
    const float reflect_ior = m.transmission_is_coverage && m.ior == 1.0f ? 1.5f : m.ior;
    s.layers = evaluate_layers(m.pbr.layers, reflect_ior, si, s.wo, side, textures, cone_width, detail);
    const PhongTerms p = s.layers.any_layer() || !s.layers.default_fresnel()
                             ? pbr_to_phong(kd, metallic, roughness, s.layers, glm::dot(s.n, s.wo))
                             : pbr_to_phong(kd, metallic, roughness);
    // KHR_materials_transmission: metal lets nothing through; what passes is tinted by the base
    // colour and blurred by the roughness (Whitted: refracted rays spread like glossy ones).
    // (BLEND's transmission is coverage: what the surface does not cover passes untinted.)
    if (!m.transmission_is_coverage) transmission *= 1.0f - s.metallic;
    s.transmission_factor = max_component(transmission);
    s.diffuse = p.kd * (Vec3(1.0f) - transmission);
    if (!m.transmission_is_coverage) transmission *= kd;
    s.refraction_glossy = s.transmission_factor > 0.0f && !m.transmission_is_coverage ? p.glossy : 0.0f;
    s.specular = p.ks;
    s.shininess = p.shininess;
    s.reflectivity = p.reflectivity;
    s.glossy = p.glossy;
  } else {
    s.transmission_factor = max_component(transmission);
    s.diffuse = kd * (Vec3(1.0f) - transmission);
    s.specular = m.ks;
    if (detail.textures && m.specular_texture.present())
      s.specular *= slot_at(m.specular_texture, si, textures, -s.wo, cone_width, detail);
    s.shininess = m.shininess;
    s.reflectivity = m.reflectivity;
    s.glossy = m.glossy;
  }
  s.transmission = transmission;
  s.ior = m.ior;
  s.absorption = m.absorption;
  s.emission = own_emission(m, si, textures, -s.wo, cone_width, detail);
  if (m.unlit) {  // shown as it is: nothing reflected, scattered or passed on
    s.emission += kd;
    s.diffuse = s.specular = s.reflectivity = s.transmission = Vec3(0.0f);
    s.transmission_factor = 0.0f;
    s.pbr = false;
  }
  return s;
}

}  // namespace rt
