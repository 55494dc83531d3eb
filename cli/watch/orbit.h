// The page's orbit: the scene's camera turned about the point it looks at (its focus distance
// ahead), by `yaw` degrees about its up direction and `pitch` degrees up (looking down more),
// keeping its distance, projection and lens. Only the preview turns: the scene file stays as it is.
#pragma once

#include <algorithm>

#include <glm/gtc/quaternion.hpp>

#include "core/camera.h"

namespace rt {

// The page keeps the pitch short of straight up or down, where "up" would be lost.
inline constexpr float kMaxOrbitPitch = 89.0f;

inline Camera orbit(const Camera& camera, float yaw_degrees, float pitch_degrees) {
  if (yaw_degrees == 0.0f && pitch_degrees == 0.0f) return camera;
  const float distance = std::max(camera.focus_distance, 1e-3f);
  const Vec3 target = camera.position + camera.forward * distance;
  const glm::quat turn =
      glm::angleAxis(radians(yaw_degrees), camera.up) *
      glm::angleAxis(-radians(std::clamp(pitch_degrees, -kMaxOrbitPitch, kMaxOrbitPitch)), camera.right);
  Camera c = camera;
  c.aim(target + turn * (camera.position - target), target, turn * camera.up);
  return c;
}

}  // namespace rt
