// How a glTF metallic-roughness material becomes our Phong material (documented in README.md):
//   kd        = base * (1 - metallic * (1 - roughness))   rough metal still scatters its colour
//   ks        = mix(0.04, base, metallic) * (1 - roughness)  dielectrics reflect ~4 %
//   shininess = clamp(2 / roughness^4 - 2, 1, 4096)      Blinn-Phong exponent of the same lobe width
// (alpha = roughness^2 and n = 2 / alpha^2 - 2, Walter et al. 2007).
#pragma once

#include <algorithm>

#include "core/material.h"

namespace rt {

inline Material pbr_to_phong(Vec3 base_colour, float metallic, float roughness) {
  metallic = std::clamp(metallic, 0.0f, 1.0f);
  roughness = std::clamp(roughness, 0.0f, 1.0f);
  Material m;
  m.kd = base_colour * (1.0f - metallic * (1.0f - roughness));
  m.ks = glm::mix(Vec3(0.04f), base_colour, metallic) * (1.0f - roughness);
  const float r4 = roughness * roughness * roughness * roughness;
  m.shininess = r4 > 0.0f ? std::clamp(2.0f / r4 - 2.0f, 1.0f, 4096.0f) : 4096.0f;
  return m;
}

}  // namespace rt
