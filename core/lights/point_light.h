// Point light with the proposal's quadratic attenuation: radiance arriving from it at distance d
// is colour * intensity / (c0 + c1 d + c2 d^2).
#pragma once

#include "core/math.h"

namespace rt {

struct PointLight {
  Vec3 position{0.0f};
  Vec3 colour{1.0f};  // linear RGB, already multiplied by the scene's "intensity"
  float c0 = 1.0f, c1 = 0.0f, c2 = 0.0f;

  float attenuation(float distance) const { return 1.0f / (c0 + distance * (c1 + distance * c2)); }
};

}  // namespace rt
