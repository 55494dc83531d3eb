// Material parameters as plain data. How they are evaluated lives in materials/.
#pragma once

#include "core/math.h"
#include "core/texture/texture_mapping.h"

namespace rt {

// The proposal's Phong material plus what reflection, refraction and glossy reflection add.
// Every default keeps an older scene meaning the same: an opaque, non-reflecting surface.
struct Material {
  Vec3 kd{0.8f};            // diffuse reflectance, linear RGB in [0, 1]
  Vec3 ks{0.0f};            // specular reflectance, linear RGB in [0, 1]
  float shininess = 32.0f;  // Phong exponent, > 0: larger = smaller, sharper highlight
  Vec3 reflectivity{0.0f};  // weight of the mirror-reflected colour, in [0, 1]
  Vec3 transmission{0.0f};  // weight of the light passing through (split by Fresnel), in [0, 1]
  float ior = 1.5f;         // index of refraction of the inside, > 0; used where transmission > 0
  Vec3 absorption{0.0f};    // Beer-Lambert coefficient per unit distance inside, >= 0
  float glossy = 0.0f;      // blur-square width of reflections (0 = perfect mirror), >= 0
  // Surface detail (README, "Textures"). A colour texture replaces kd and a specular texture ks:
  // kd and ks then multiply them, and default to 1 when the scene does not give them.
  TextureSlot texture;
  TextureSlot specular_texture;
  BumpMap bump;
  NormalMap normal_map;

  bool transmissive() const { return max_component(transmission) > 0.0f; }
  bool absorbing() const { return max_component(absorption) > 0.0f; }
};

}  // namespace rt
