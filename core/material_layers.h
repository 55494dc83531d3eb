// The ratified glTF PBR extensions that layer on the metallic-roughness model, as plain data
// (docs/scene-format.md, "glTF materials"). Each factor's default leaves the base model as it is;
// each texture multiplies its factor in the channel the extension names. How they are evaluated:
// materials/evaluated_surface.cpp (per point), materials/bsdf.cpp (path tracer),
// materials/pbr_to_phong.h (Whitted's approximation).
#pragma once

#include "core/math.h"
#include "core/texture/texture_slot.h"

namespace rt {

// KHR_materials_clearcoat: a second, colourless GGX layer (F0 0.04) on top of everything.
struct ClearcoatLayer {
  float factor = 0.0f;  // x texture R
  TextureSlot texture;
  float roughness = 0.0f;  // x roughness texture G
  TextureSlot roughness_texture;
  NormalMap normal_map;  // the coat's own; without one the coat follows the geometry, not the base's map
};

// KHR_materials_sheen: a Charlie microfibre lobe (Estevez and Kulla 2017) over the base, which
// keeps 1 - max(colour) x the sheen's directional albedo.
struct SheenLayer {
  Vec3 color{0.0f};  // x colour texture RGB (sRGB)
  TextureSlot color_texture;
  float roughness = 0.0f;  // x roughness texture A
  TextureSlot roughness_texture;
};

// KHR_materials_specular: scales the dielectric's Fresnel, F0 by colour x factor and F90 by factor.
struct SpecularLayer {
  float factor = 1.0f;  // x texture A
  TextureSlot texture;
  Vec3 color{1.0f};  // x colour texture RGB (sRGB)
  TextureSlot color_texture;
};

// KHR_materials_anisotropy: the GGX lobe stretched along a direction in the tangent plane,
// alpha_t = mix(alpha, 1, strength^2) along it and alpha across.
struct AnisotropyLayer {
  float strength = 0.0f;  // x texture B
  float rotation = 0.0f;  // radians, counter-clockwise from the tangent
  TextureSlot texture;    // RG: the direction in tangent space, as (x + 1) / 2; B strength
};

// KHR_materials_iridescence: a thin film on the surface (Belcour and Barla 2017), whose Fresnel
// term replaces the base's by `factor`.
struct IridescenceLayer {
  float factor = 0.0f;  // x texture R
  TextureSlot texture;
  float ior = 1.3f;              // the film's index
  float thickness_min = 100.0f;  // nanometres, where the thickness texture's G is 0
  float thickness_max = 400.0f;  // and where it is 1 (or everywhere without the texture)
  TextureSlot thickness_texture;
};

struct PbrLayers {
  ClearcoatLayer clearcoat;
  SheenLayer sheen;
  SpecularLayer specular;
  AnisotropyLayer anisotropy;
  IridescenceLayer iridescence;
  // KHR_materials_dispersion: 20 / the Abbe number; 0 = none. The path tracer refracts each path
  // at one wavelength's index; Whitted uses `ior` for every colour.
  float dispersion = 0.0f;
};

}  // namespace rt
