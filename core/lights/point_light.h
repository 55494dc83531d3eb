// Point light: radiance arriving from it at distance d is colour * intensity / (c0 + c1 d + c2 d^2).
#pragma once

#include "core/lights/attenuation.h"
#include "core/math.h"

namespace rt {

struct PointLight {
  Vec3 position{0.0f};
  Vec3 color{1.0f};  // linear RGB, already multiplied by the scene's "intensity"
  Attenuation attenuation;
};

}  // namespace rt
