// The shading stage: between the hit and the integrator. Scene::surface gives the geometry of a
// hit; evaluate_surface turns it and the hit's material into everything the integrator reads,
// with the normals turned to face the ray. Textures change kd and ks here, and bump and normal
// maps the shading normal, at this point and nowhere else.
#pragma once

#include <optional>
#include <vector>

#include "core/hit.h"
#include "core/material.h"
#include "core/render_settings.h"
#include "core/texture/texture.h"
#include "materials/evaluated_layers.h"
#include "materials/pbr_to_phong.h"

namespace rt {

// glTF's metallic-roughness at a point, for the path tracer's microfacet model.
struct PbrSurfaceTerms {
  Vec3 base_color{0.0f};  // textured, times COLOR_0
  float metallic = 0.0f;
  float roughness = 1.0f;
  EvaluatedLayers layers;  // clearcoat, sheen, specular, anisotropy, iridescence, dispersion
};

struct EvaluatedSurface {
  Vec3 position{0.0f};
  Vec3 position_error{0.0f};  // SurfaceInteraction's, for where rays leave (core/ray.h)
  Vec3 shadow_lift{0.0f};     // shadow rays start at position + shadow_lift (SurfaceInteraction's)
  Vec3 n{0.0f, 0.0f, 1.0f};   // unit shading normal, on the side the ray came from
  Vec3 ng{0.0f, 0.0f, 1.0f};  // unit geometric normal, same side
  Vec3 wo{0.0f, 0.0f, 1.0f};  // unit, towards where the ray came from
  bool entering = true;       // the ray arrived from the outward side (for refraction)
  // The material at this point, and the one whose inside lies behind it (refraction's medium:
  // the same but on a CSG solid's cut surfaces).
  uint32_t material = 0;
  uint32_t medium = 0;
  Vec3 diffuse{0.0f};  // kd x (1 - transmission): light that passes through is not also scattered
  Vec3 specular{0.0f};
  float shininess = 32.0f;
  Vec3 reflectivity{0.0f};
  Vec3 transmission{0.0f};           // what passes (glTF: tinted by the base colour, none through metal)
  float transmission_factor = 0.0f;  // how much passes, untinted: the share the dielectric takes
  float refraction_glossy = 0.0f;    // blur-square width of refracted rays (glTF: from roughness, as `glossy`)
  float ior = 1.5f;
  Vec3 absorption{0.0f};
  float glossy = 0.0f;
  Vec3 emission{0.0f};  // radiance the surface gives off itself (emissive, unlit)
  // glTF's model at this point (the Phong terms above are Whitted's conversion of it); none on a
  // Phong material, whose record then writes none of its 108 bytes, a third of the record's
  // stores at every hit (refraction.json 0.7% fewer instructions; the time the same, measured).
  std::optional<PbrSurfaceTerms> pbr;
  // The primitive it is on (Hit::prim), where the integrator records it: a ray that leaves it
  // walks less (Scene::intersect's RayStart). Last: the fields above keep their offsets.
  uint32_t prim = kNoPrimitive;

  bool transmissive() const { return max_component(transmission) > 0.0f; }
};

// What a material gives at a point, before the hit's geometry joins it in an EvaluatedSurface.
struct MaterialTerms {
  Vec3 n;  // unit shading normal, on the side the ray came from
  PhongTerms phong;
  Vec3 transmission{0.0f};
  float transmission_factor = 0.0f;
  float refraction_glossy = 0.0f;
  Vec3 emission{0.0f};
  std::optional<PbrSurfaceTerms> pbr;  // glTF's model only
};

// The record of a hit: its geometry, `terms` and the material's own numbers. The one place an
// EvaluatedSurface is written whole, every field named: a record made and then filled in was
// zeroed first (288 bytes; refraction.json 0.989x the time without).
inline EvaluatedSurface evaluated_surface(const Material& m, const SurfaceInteraction& si, Vec3 wo, float side,
                                          const MaterialTerms& terms) {
  return EvaluatedSurface{.position = si.position,
                          .position_error = si.position_error,
                          .shadow_lift = si.shadow_lift,
                          .n = terms.n,
                          .ng = side * si.geometric_normal,
                          .wo = wo,
                          .entering = si.front_face,
                          .material = si.material,
                          .medium = si.medium == kOwnMedium ? si.material : si.medium,
                          .diffuse = terms.phong.kd,
                          .specular = terms.phong.ks,
                          .shininess = terms.phong.shininess,
                          .reflectivity = terms.phong.reflectivity,
                          .transmission = terms.transmission,
                          .transmission_factor = terms.transmission_factor,
                          .refraction_glossy = terms.refraction_glossy,
                          .ior = m.ior,
                          .absorption = m.absorption,
                          .glossy = terms.phong.glossy,
                          .emission = terms.emission,
                          // Copied only where there are terms: an optional of a trivially copyable
                          // type is copied whole, its unset payload's 108 bytes too.
                          .pbr = terms.pbr ? terms.pbr : std::nullopt,
                          .prim = kNoPrimitive};
}

// evaluate_surface_unit for any material: textures, bump and normal maps, glTF's model, unlit.
EvaluatedSurface evaluate_mapped_surface(const Material& m, const SurfaceInteraction& si, Vec3 unit_direction,
                                         const std::vector<Texture>& textures, float cone_width,
                                         SurfaceDetailSwitches detail);

// evaluate_surface_unit's record for a material whose uniform_phong() holds, made inline: its terms
// are the material's own numbers, evaluate_mapped_surface's floats. The common case: a call less
// a hit, and no texture, map or glTF test (refraction.json 4.5% fewer instructions, 0.95x the
// time; the path-traced Cornell box 3.2% fewer). The Whitted integrator asks the scene which
// materials are uniform (Scene::is_uniform_phong), a byte, not eight of the material's fields.
inline EvaluatedSurface uniform_phong_surface(const Material& m, const SurfaceInteraction& si, Vec3 unit_direction) {
  // Shade the side the ray sees: both sides of an opaque surface are lit like its front.
  const float side = si.front_face ? 1.0f : -1.0f;
  const Vec3 kd = m.kd * Vec3(si.color);
  return evaluated_surface(m, si, -unit_direction, side,
                           MaterialTerms{.n = side * si.shading_normal,
                                         .phong = {.kd = kd * (Vec3(1.0f) - m.transmission),
                                                   .ks = m.ks,
                                                   .shininess = m.shininess,
                                                   .reflectivity = m.reflectivity,
                                                   .glossy = m.glossy},
                                         .transmission = m.transmission,
                                         .transmission_factor = max_component(m.transmission),
                                         .refraction_glossy = 0.0f,
                                         .emission = m.emission,
                                         .pbr = std::nullopt});
}

// `unit_direction` is the direction of the ray that hit, of length 1 (glm::normalize's bits); `cone_width` the
// world-space width of its ray cone at the hit (one pixel's footprint; 0 = the finest mip level), which picks the mip
// level of trilinear textures; `detail` can switch textures or bumps off. Never allocates.
inline EvaluatedSurface evaluate_surface_unit(const Material& m, const SurfaceInteraction& si, Vec3 unit_direction,
                                              const std::vector<Texture>& textures, float cone_width = 0.0f,
                                              SurfaceDetailSwitches detail = {}) {
  return m.uniform_phong() ? uniform_phong_surface(m, si, unit_direction)
                           : evaluate_mapped_surface(m, si, unit_direction, textures, cone_width, detail);
}

// The same for a ray of any length. (evaluate_surface_unit is for a caller that has the length
// already: the Whitted integrator's, which takes one square root a hit, not two.)
inline EvaluatedSurface evaluate_surface(const Material& m, const SurfaceInteraction& si, Vec3 ray_direction,
                                         const std::vector<Texture>& textures, float cone_width = 0.0f,
                                         SurfaceDetailSwitches detail = {}) {
  return evaluate_surface_unit(m, si, glm::normalize(ray_direction), textures, cone_width, detail);
}

// evaluate_surface(...).emission alone: what the surface gives off towards where a ray of
// `ray_direction` came from, without the rest of the material (light sampling's emitter points).
Vec3 emitted_radiance(const Material& m, const SurfaceInteraction& si, Vec3 ray_direction,
                      const std::vector<Texture>& textures, float cone_width = 0.0f, SurfaceDetailSwitches detail = {});

}  // namespace rt
