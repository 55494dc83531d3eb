// Material parameters as plain data. How they are evaluated lives in materials/.
#pragma once

#include "core/math.h"

namespace rt {

// The proposal's Phong material. Later capabilities (reflection, refraction, glossy, textures,
// bump maps) add fields here; the defaults keep older scenes meaning the same.
struct Material {
  Vec3 kd{0.8f};            // diffuse reflectance, linear RGB in [0, 1]
  Vec3 ks{0.0f};            // specular reflectance, linear RGB in [0, 1]
  float shininess = 32.0f;  // Phong exponent, > 0: larger = smaller, sharper highlight
};

}  // namespace rt
