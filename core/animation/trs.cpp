#include "core/animation/trs.h"

namespace rt {

Mat4 Trs::matrix() const {
  Mat4 m = glm::mat4_cast(rotation);
  m[0] *= scale.x;
  m[1] *= scale.y;
  m[2] *= scale.z;
  m[3] = Vec4(translation, 1.0f);
  return m;
}

Quat euler_degrees_to_quat(Vec3 degrees) {
  const Vec3 r = glm::radians(degrees);
  return glm::angleAxis(r.z, Vec3(0, 0, 1)) * glm::angleAxis(r.y, Vec3(0, 1, 0)) * glm::angleAxis(r.x, Vec3(1, 0, 0));
}

Quat axis_angle_to_quat(Vec3 axis, float degrees) {
  return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

}  // namespace rt
