// Material parameters as plain data. How they are evaluated lives in materials/.
#pragma once

#include <array>
#include <type_traits>

#include "core/material_layers.h"
#include "core/math.h"
#include "core/texture/texture_slot.h"

namespace rt {

// glTF's metallic-roughness model, kept as it is and converted to Phong terms at each shading
// point (materials/pbr_to_phong.h), so that a metallicRoughness texture can vary it. When
// `enabled`, Material::kd is the base colour and ks, shininess, reflectivity and glossy follow
// from it; the material's own values of those are not used.
struct MetallicRoughness {
  bool enabled = false;
  float metallic = 1.0f;
  float roughness = 1.0f;
  TextureSlot texture;  // glTF's metallicRoughnessTexture: G scales roughness, B metallic (linear)
  PbrLayers layers;     // clearcoat, sheen, specular, anisotropy, iridescence, dispersion
};

// glTF's alphaMode MASK: the surface is not there where coverage < cutoff, for every ray
// (camera, reflection, refraction, shadow). Coverage = factor x texture x the vertex colour's
// alpha. (BLEND is mapped onto this and onto transmission by io/gltf/materials.cpp.)
struct AlphaCutoutParams {
  bool enabled = false;
  // glTF's BLEND: coverage is a fraction of the surface, not a mask. The path tracer keeps each
  // point with probability = coverage (stochastic transparency); Whitted cuts at `cutoff`.
  bool blend = false;
  float factor = 1.0f;  // baseColorFactor's alpha
  float cutoff = 0.5f;
  TextureSlot texture;  // the base colour image's alpha channel, as a grey texture
};

// The proposal's Phong material plus what reflection, refraction and glossy reflection add.
// Every default keeps an older scene meaning the same: an opaque, non-reflecting surface.
struct Material {
  Vec3 kd{0.8f};                     // diffuse reflectance, linear RGB in [0, 1]
  Vec3 ks{0.0f};                     // specular reflectance, linear RGB in [0, 1]
  float shininess = 32.0f;           // Phong exponent, > 0: larger = smaller, sharper highlight
  Vec3 reflectivity{0.0f};           // weight of the mirror-reflected colour, in [0, 1]
  Vec3 transmission{0.0f};           // weight of the light passing through (split by Fresnel), in [0, 1]
  TextureSlot transmission_texture;  // glTF's transmissionTexture: its red channel scales transmission (linear)
  // glTF's alphaMode BLEND made the transmission (1 - alpha, unbent): the surface covers only part
  // of each point, and what it does not cover lets light through untinted, metal or not.
  bool transmission_is_coverage = false;
  float ior = 1.5f;       // index of refraction of the inside, > 0; used where transmission > 0
  Vec3 absorption{0.0f};  // Beer-Lambert coefficient per unit distance inside, >= 0
  float glossy = 0.0f;    // blur-square width of reflections (0 = perfect mirror), >= 0
  // Surface detail (docs/rendering.md, "Textures"). A colour texture replaces kd and a specular texture ks:
  // kd and ks then multiply them, and default to 1 when the scene does not give them.
  TextureSlot texture;
  TextureSlot specular_texture;
  BumpMap bump;
  NormalMap normal_map;
  // Light the surface gives off itself (glTF's emissive x KHR_materials_emissive_strength), in
  // the units of radiance; seen by camera, reflection and refraction rays, not a light source.
  Vec3 emission{0.0f};
  TextureSlot emission_texture;  // multiplies `emission`
  // glTF's doubleSided false: the back of a triangle is not there for camera, reflection,
  // refraction and glossy rays (they pass through it); shadow rays still stop at it. Ignored for
  // transmissive materials, whose back faces are where rays leave the glass.
  bool single_sided = false;
  // KHR_materials_unlit: the (textured) base colour is shown as it is, without lighting.
  bool unlit = false;
  MetallicRoughness pbr;
  AlphaCutoutParams cutout;

  // Every texture slot, for whoever renumbers textures (a glTF file's, added to a scene's).
  std::array<TextureSlot*, 18> texture_slots() { return slots_of(*this); }
  std::array<const TextureSlot*, 18> texture_slots() const { return slots_of(*this); }

  // Whether shading reads the surface's texture coordinates: a texture in any slot (each is
  // placed by them or by a projection), or an anisotropy direction without a tangent (dP/du).
  bool reads_texcoords() const {
    for (const TextureSlot* slot : texture_slots())
      if (slot->present()) return true;
    return pbr.layers.anisotropy.strength > 0.0f;
  }

  bool transmissive() const { return max_component(transmission) > 0.0f; }
  // What passes through the material, before textures: its transmission; under glTF's model
  // tinted by the base colour factor, and none through metal (KHR_materials_transmission).
  Vec3 transmittance() const {
    return pbr.enabled && !transmission_is_coverage ? transmission * kd * (1.0f - pbr.metallic) : transmission;
  }
  bool absorbing() const { return max_component(absorption) > 0.0f; }
  // A Phong material the same all over: no texture or map that varies it, not glTF's model, lit.
  // Its shading terms are its own numbers (uniform_phong_surface, materials/evaluated_surface.h).
  bool uniform_phong() const {
    return !pbr.enabled && !unlit && !texture.present() && !specular_texture.present() &&
           !transmission_texture.present() && !emission_texture.present() && !bump.height.present() &&
           !normal_map.map.present();
  }

 private:
  template <class M>  // Material or const Material
  static std::array<std::conditional_t<std::is_const_v<M>, const TextureSlot*, TextureSlot*>, 18> slots_of(M& m) {
    auto& l = m.pbr.layers;
    return {&m.texture,
            &m.specular_texture,
            &m.bump.height,
            &m.normal_map.map,
            &m.emission_texture,
            &m.pbr.texture,
            &m.cutout.texture,
            &m.transmission_texture,
            &l.clearcoat.texture,
            &l.clearcoat.roughness_texture,
            &l.clearcoat.normal_map.map,
            &l.sheen.color_texture,
            &l.sheen.roughness_texture,
            &l.specular.texture,
            &l.specular.color_texture,
            &l.anisotropy.texture,
            &l.iridescence.texture,
            &l.iridescence.thickness_texture};
  }
};

}  // namespace rt
