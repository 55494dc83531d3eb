// A node's local transform kept as its parts, so that animation tracks can replace one part:
// M = T * R * S (scale first, then rotate, then translate), as glTF defines it.
#pragma once

#include <glm/gtc/quaternion.hpp>

#include "core/math.h"

namespace rt {

using Quat = glm::quat;  // GLM's constructor takes w first: Quat(w, x, y, z)

struct Trs {
  Vec3 translation{0.0f};
  Quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // unit
  Vec3 scale{1.0f};

  Mat4 matrix() const;
};

// The rotation of the scene format's Euler angles (degrees): about X, then Y, then Z
// (R = Rz * Ry * Rx, as compose_trs in core/transform.h).
Quat euler_degrees_to_quat(Vec3 degrees);
// A rotation of `degrees` about `axis` (any non-zero length).
Quat axis_angle_to_quat(Vec3 axis, float degrees);

}  // namespace rt
