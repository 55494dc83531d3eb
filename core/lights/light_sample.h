// What sampling a light gives a shading point: the light sampling interface every kind of light
// answers (core/lights/light.h for the scene's lights, core/lights/emitters.h for emissive
// surfaces, core/lights/environment.h for the sky), and both integrators read.
#pragma once

#include "core/math.h"

namespace rt {

struct LightSample {
  Vec3 direction{0.0f, 1.0f, 0.0f};  // unit, from the point towards the light
  float distance = 0.0f;             // to the point sampled on the light; kInfinity from afar
  // Arriving at the point, shadow not yet tested. A delta light's (point, spot, directional):
  // its colour x attenuation (x cone); a surface's or the sky's: the radiance it emits along
  // `direction` (a rect light's colour, an emissive material's emission).
  Vec3 radiance{0.0f};
  // Density of `direction` per unit solid angle; 0: no sample (the light cannot reach the point,
  // or the point drawn lies where the light does not emit). 1 for a delta light.
  float pdf = 0.0f;
  bool delta = false;  // a point, spot or directional light: no ray finds it by chance
  // The cosine between the light surface's normal and the direction back to the point, 0 behind a
  // one-sided light (1 for a delta light and the sky): Whitted's rule for a rect light reads it
  // (core/lights/rect_light.h).
  float cos_light = 1.0f;
};

// A sample of a light at `to`, seen from `from`, arriving with `radiance`.
inline LightSample light_sample_towards(Vec3 from, Vec3 to, Vec3 radiance) {
  LightSample s;
  const Vec3 d = to - from;
  s.distance = glm::length(d);
  s.direction = s.distance > 0.0f ? d / s.distance : Vec3(0.0f, 1.0f, 0.0f);
  s.radiance = radiance;
  return s;
}

}  // namespace rt
