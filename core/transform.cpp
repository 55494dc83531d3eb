#include "core/transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace rt {

std::optional<Transform> make_transform(const Mat4& to_world) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(to_world[c][r])) return std::nullopt;
  const Mat3 linear(to_world);
  // Relative test: compare the determinant with the product of the column lengths, so that a
  // uniformly tiny (but valid) object is not called singular while a flattened one is. In
  // double, where neither a scale of 1e38 nor one of 1e-20 cubed overflows or underflows.
  const glm::dmat3 d(linear);
  const double det = glm::determinant(d);
  const double scale = glm::length(d[0]) * glm::length(d[1]) * glm::length(d[2]);
  if (!(scale > 0.0) || !(std::fabs(det) > 1e-6 * scale)) return std::nullopt;
  Transform t;
  t.to_world = to_world;
  // Inverted in double: a float 4x4 inverse forms determinants of products of four entries,
  // which overflow for scales near 1e38 or underflow for 1e-20, and is less accurate anyway.
  t.to_object = Mat4(glm::inverse(glm::dmat4(to_world)));
  t.normal_to_world = Mat3(glm::transpose(glm::inverse(d)));
  // A valid matrix whose inverse leaves single precision (a scale of 1e-39) is no use either.
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(t.to_object[c][r]) || (c < 3 && r < 3 && !std::isfinite(t.normal_to_world[c][r])))
        return std::nullopt;
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
