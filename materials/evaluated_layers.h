// glTF's layered material extensions (core/material_layers.h) at one shading point: their factors
// times their textures, the clearcoat's normal and the anisotropy's direction in world space.
// The defaults leave the metallic-roughness model as it is.
#pragma once

#include <vector>

#include "core/hit.h"
#include "core/material_layers.h"
#include "core/render_settings.h"
#include "core/texture/texture.h"

namespace rt {

struct EvaluatedLayers {
  // The dielectric's Fresnel: F0 from the index (KHR_materials_ior) times KHR_materials_specular's
  // colour and factor, F90 its factor. (0.04 and 1: the core specification's.)
  Vec3 dielectric_f0{0.04f};
  float dielectric_f90 = 1.0f;
  float clearcoat = 0.0f;
  float clearcoat_roughness = 0.0f;
  Vec3 clearcoat_n{0.0f, 0.0f, 1.0f};  // unit, on the ray's side, facing it
  Vec3 sheen_color{0.0f};
  float sheen_roughness = 0.0f;
  float anisotropy = 0.0f;                      // strength in [0, 1]
  Vec3 anisotropy_direction{1.0f, 0.0f, 0.0f};  // world, along the surface (made perpendicular to n by the BSDF)
  float iridescence = 0.0f;
  float iridescence_ior = 1.3f;
  float iridescence_thickness = 400.0f;  // nanometres
  float dispersion = 0.0f;

  bool any_layer() const {
    return clearcoat > 0.0f || sheen_color != Vec3(0.0f) || anisotropy > 0.0f || iridescence > 0.0f;
  }
  bool default_fresnel() const { return dielectric_f0 == Vec3(0.04f) && dielectric_f90 == 1.0f && iridescence == 0.0f; }
};

// `wo` is the unit direction towards where the ray came from, `side` +1 where the ray meets the
// outward face, else -1; `reflect_ior` the index that sets the dielectric's F0.
EvaluatedLayers evaluate_layers(const PbrLayers& layers, float reflect_ior, const SurfaceInteraction& si, Vec3 wo,
                                float side, const std::vector<Texture>& textures, float cone_width,
                                SurfaceDetailSwitches detail);

}  // namespace rt
