// Spot light (glTF KHR_lights_punctual): a point light whose emission fades from full inside
// the inner cone to none outside the outer cone, with glTF's smooth falloff t^2, where
// t = clamp((cos angle - cos outer) / (cos inner - cos outer), 0, 1).
#pragma once

#include <algorithm>

#include "core/lights/attenuation.h"
#include "core/math.h"

namespace rt {

struct SpotLight {
  Vec3 position{0.0f};
  Vec3 direction{0.0f, 0.0f, -1.0f};  // unit: where the cone points (glTF: the node's -Z)
  Vec3 color{1.0f};
  Attenuation attenuation{0.0f, 0.0f, 1.0f};  // inverse square
  float cos_inner = 1.0f;                     // cos of the inner cone's half-angle
  float cos_outer = 0.70710678f;              // cos of the outer cone's half-angle (< cos_inner)

  // The fraction emitted towards unit direction `towards` (from the light).
  float cone(Vec3 towards) const {
    const float t =
        std::clamp((glm::dot(towards, direction) - cos_outer) / std::max(cos_inner - cos_outer, 1e-6f), 0.0f, 1.0f);
    return t * t;
  }
};

}  // namespace rt
