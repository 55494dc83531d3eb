#include "core/transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace rt {

std::optional<Transform> make_transform(const Mat4& to_world) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(to_world[c][r])) return std::nullopt;
  const Mat3 linear(to_world);
  const float det = glm::determinant(linear);
  // Relative test: compare the determinant with the product of the column lengths, so that a
  // uniformly tiny (but valid) object is not called singular while a flattened one is.
  const float scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
  if (!(scale > 0.0f) || !(std::fabs(det) > 1e-6f * scale)) return std::nullopt;
  Transform t;
  t.to_world = to_world;
  t.to_object = glm::inverse(to_world);
  t.normal_to_world = glm::transpose(glm::inverse(linear));
  return t;
}

Mat4 compose_trs(Vec3 translate, Vec3 rotate_degrees, Vec3 scale) {
  Mat4 m = glm::translate(Mat4(1.0f), translate);
  m = glm::rotate(m, radians(rotate_degrees.z), Vec3(0, 0, 1));
  m = glm::rotate(m, radians(rotate_degrees.y), Vec3(0, 1, 0));
  m = glm::rotate(m, radians(rotate_degrees.x), Vec3(1, 0, 0));
  return glm::scale(m, scale);
}

Aabb transform_bounds(const Mat4& m, const Aabb& box) {
  if (box.empty()) return box;
  Aabb out;
  out.lo = out.hi = Vec3(m[3]);
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) {
      const float a = m[col][row] * box.lo[col];
      const float b = m[col][row] * box.hi[col];
      out.lo[row] += std::min(a, b);
      out.hi[row] += std::max(a, b);
    }
  }
  return out;
}

}  // namespace rt
