// Lights are a closed set (point now; rectangular area lights next), dispatched statically.
#pragma once

#include <variant>

#include "core/lights/point_light.h"

namespace rt {

using Light = std::variant<PointLight>;

// One sample of the light seen from a surface point.
struct LightSample {
  Vec3 direction{0.0f};  // unit, from the point towards the light
  float distance = 0.0f;
  Vec3 radiance{0.0f};  // arriving at the point, attenuation applied, shadow not yet tested
};

inline LightSample sample_light(const PointLight& light, Vec3 point) {
  LightSample s;
  const Vec3 to_light = light.position - point;
  s.distance = glm::length(to_light);
  s.direction = s.distance > 0.0f ? to_light / s.distance : Vec3(0.0f, 1.0f, 0.0f);
  s.radiance = light.colour * light.attenuation(s.distance);
  return s;
}

inline LightSample sample_light(const Light& light, Vec3 point) {
  return std::visit([&](const auto& l) { return sample_light(l, point); }, light);
}

}  // namespace rt
