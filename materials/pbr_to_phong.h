// How glTF's metallic-roughness parameters become our Phong terms (docs/scene-format.md, "glTF materials"),
// per shading point, so that metallicRoughness textures vary them across a surface:
//   kd           = base * (1 - metallic * (1 - roughness))    rough metal still scatters its colour
//   F0           = mix(0.04, base, metallic)                   dielectrics reflect ~4 % head-on
//   ks           = F0 * (1 - roughness)                        the highlight: the lights' reflection
//   shininess    = clamp(2 / roughness^4 - 2, 1, 4096)         Blinn-Phong exponent of the same lobe width
//   reflectivity = F0 * (1 - roughness)^2                      the mirror image of the rest of the scene
//   glossy       = 2 * roughness^2                             blur-square width of that image
// (alpha = roughness^2 and n = 2 / alpha^2 - 2, Walter et al. 2007; a blur square of width
// 2 alpha spreads the reflected rays about as far as the microfacet lobe.)
#pragma once

#include <algorithm>

#include "core/math.h"
#include "materials/evaluated_layers.h"

namespace rt {

struct PhongTerms {
  Vec3 kd{0.0f};
  Vec3 ks{0.0f};
  float shininess = 1.0f;
  Vec3 reflectivity{0.0f};
  float glossy = 0.0f;
};

inline PhongTerms pbr_to_phong(Vec3 base_color, float metallic, float roughness) {
  metallic = std::clamp(metallic, 0.0f, 1.0f);
  roughness = std::clamp(roughness, 0.0f, 1.0f);
  const float smooth = 1.0f - roughness;
  const Vec3 f0 = glm::mix(Vec3(0.04f), base_color, metallic);
  PhongTerms p;
  p.kd = base_color * (1.0f - metallic * smooth);
  p.ks = f0 * smooth;
  const float r2 = roughness * roughness, r4 = r2 * r2;
  p.shininess = r4 > 0.0f ? std::clamp(2.0f / r4 - 2.0f, 1.0f, 4096.0f) : 4096.0f;
  p.reflectivity = f0 * (smooth * smooth);
  p.glossy = 2.0f * r2;
  return p;
}

// The same with glTF's layered extensions, as Whitted approximates them (docs/rendering.md,
// "glTF material extensions"), seen at `cos_view` from the shading normal:
//   specular, ior   F0 = mix(the dielectric's F0 (x F90 when it is the grazing limit), base, metallic)
//   iridescence     F0 mixed with the thin film's reflectance at the viewing angle, by its factor
//   anisotropy      one isotropic lobe of the geometric mean width, sqrt(alpha_t alpha_b)
//   sheen           kd, ks, reflectivity x (1 - max(colour) E(view)); kd + colour E(view)
//   clearcoat       all x (1 - c F_coat(view)); ks and reflectivity + c F_coat(view) with the
//                   coat's sharpness, glossy width and exponent mixed by the two reflections' shares
//                   (the coat shares the base's normal)
//   dispersion      none: one index for every colour
PhongTerms pbr_to_phong(Vec3 base_color, float metallic, float roughness, const EvaluatedLayers& layers,
                        float cos_view);

}  // namespace rt
