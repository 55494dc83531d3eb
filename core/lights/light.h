// Lights are a closed set, dispatched statically: point, spot and directional lights (hard
// shadows, one shadow ray) and rectangular area lights (soft shadows, render.shadow_samples rays
// stratified over the rectangle).
#pragma once

#include <variant>

#include "core/lights/directional_light.h"
#include "core/lights/point_light.h"
#include "core/lights/rect_light.h"
#include "core/lights/spot_light.h"

namespace rt {

using Light = std::variant<PointLight, RectLight, SpotLight, DirectionalLight>;

// One sample of the light seen from a surface point.
struct LightSample {
  Vec3 direction{0.0f};  // unit, from the point towards the light
  float distance = 0.0f;
  Vec3 radiance{0.0f};  // arriving at the point, attenuation applied, shadow not yet tested
};

inline LightSample light_sample_towards(Vec3 from, Vec3 to, Vec3 radiance_at_unit) {
  LightSample s;
  const Vec3 d = to - from;
  s.distance = glm::length(d);
  s.direction = s.distance > 0.0f ? d / s.distance : Vec3(0.0f, 1.0f, 0.0f);
  s.radiance = radiance_at_unit;
  return s;
}

// u in [0, 1)^2 picks the point on an area light; a point light ignores it.
inline LightSample sample_light(const PointLight& light, Vec3 point, Vec2 /*u*/) {
  LightSample s = light_sample_towards(point, light.position, light.color);
  s.radiance *= light.attenuation(s.distance);
  return s;
}

inline LightSample sample_light(const SpotLight& light, Vec3 point, Vec2 /*u*/) {
  LightSample s = light_sample_towards(point, light.position, light.color);
  s.radiance *= light.attenuation(s.distance) * light.cone(-s.direction);
  return s;
}

inline LightSample sample_light(const DirectionalLight& light, Vec3 /*point*/, Vec2 /*u*/) {
  LightSample s;
  s.direction = -light.direction;
  s.distance = kInfinity;
  s.radiance = light.color;
  return s;
}

// `unit_normal` is light.normal(), computed once by a caller that samples the light many times.
inline LightSample sample_rect_light(const RectLight& light, Vec3 unit_normal, Vec3 point, Vec2 u) {
  LightSample s = light_sample_towards(point, light.point(u), light.color);
  const float cos_light = -glm::dot(s.direction, unit_normal);
  const float emitted = light.two_sided ? std::fabs(cos_light) : std::max(0.0f, cos_light);
  s.radiance *= light.attenuation(s.distance) * emitted;
  return s;
}

inline LightSample sample_light(const RectLight& light, Vec3 point, Vec2 u) {
  return sample_rect_light(light, light.normal(), point, u);
}

inline LightSample sample_light(const Light& light, Vec3 point, Vec2 u) {
  return std::visit([&](const auto& l) { return sample_light(l, point, u); }, light);
}

// How many shadow samples a light takes: one for a point light, shadow_samples for an area light.
inline int light_sample_count(const Light& light, int shadow_samples) {
  return std::holds_alternative<RectLight>(light) ? shadow_samples : 1;
}

}  // namespace rt
