// Vector types and small numeric helpers shared by every stage.
// We use GLM's float vectors: the renderer works in single precision, and only the
// quadric root finders (shapes/quadratic.h) widen to double where cancellation hurts.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace rt {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using Mat2 = glm::mat2;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

inline float radians(float degrees) { return degrees * (kPi / 180.0f); }

inline float max_component(Vec3 v) { return std::max(v.x, std::max(v.y, v.z)); }
// |v| per component. Not glm::abs: glm applies it through a function pointer, which makes the
// compiler emit an out-of-line copy in whichever file uses it, the BVH kernels' included
// (tests/tools/check_kernel_symbols.cmake); and its x >= 0 ? x : -x, which must keep the sign of
// -0 and NaN, became a compare and a branch per component (three on a sphere's hit point, whose
// signs no predictor knows), where std::fabs is one AND.
inline Vec3 abs3(Vec3 v) { return Vec3(std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)); }
inline float max_abs_component(Vec3 v) { return max_component(abs3(v)); }

inline bool is_finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
inline bool is_finite(Vec4 v) { return is_finite(Vec3(v)) && std::isfinite(v.w); }

// Any unit vector perpendicular to n (n must be unit length). Branchless construction from
// Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
inline void orthonormal_basis(Vec3 n, Vec3& t, Vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = Vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = Vec3(c, sign + n.y * n.y * a, -n.y);
}

}  // namespace rt
