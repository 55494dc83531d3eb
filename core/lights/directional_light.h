// Directional light (glTF KHR_lights_punctual): parallel light from infinitely far away, the
// same everywhere; its shadow rays run to infinity.
#pragma once

#include "core/math.h"

namespace rt {

struct DirectionalLight {
  Vec3 direction{0.0f, -1.0f, 0.0f};  // unit: the way the light travels (glTF: the node's -Z)
  Vec3 color{1.0f};                   // arriving on a surface facing it
};

}  // namespace rt
