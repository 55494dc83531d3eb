// Bounds on the rounding error of single-precision arithmetic, for robust ray origins (Pharr,
// Jakob and Humphreys, "Physically Based Rendering", 4th ed., section 6.8). A point carries an
// absolute error bound per component: the exact point lies within +-error of the computed one.
#pragma once

#include <bit>
#include <cstdint>

#include "core/math.h"

namespace rt {

// (1 + eps)^n - 1 <= gamma(n) for n operations, eps = 2^-24 (half a float ulp at 1).
inline constexpr float float_gamma(int n) {
  constexpr float eps = std::numeric_limits<float>::epsilon() * 0.5f;
  return (static_cast<float>(n) * eps) / (1.0f - static_cast<float>(n) * eps);
}

// The next float above (below) v; +-0 step to the smallest subnormal, infinities stay.
inline float next_float_up(float v) {
  if (std::isinf(v) && v > 0.0f) return v;
  if (v == -0.0f) v = 0.0f;
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits = v >= 0.0f ? bits + 1 : bits - 1;
  return std::bit_cast<float>(bits);
}

inline float next_float_down(float v) {
  if (std::isinf(v) && v < 0.0f) return v;
  if (v == 0.0f) v = -0.0f;
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits = v > 0.0f ? bits - 1 : bits + 1;
  return std::bit_cast<float>(bits);
}

// Error bound of m * (p, 1) computed in float, for p known within +-p_error: each component is
// a sum of three products and a translation (gamma(3) of its terms' magnitudes) plus the input
// error carried through the matrix.
inline Vec3 transformed_point_error(const Mat4& m, Vec3 p, Vec3 p_error) {
  Vec3 e;
  for (int i = 0; i < 3; ++i) {  // glm is column-major: m[column][row]
    const float magnitude =
        std::fabs(m[0][i] * p.x) + std::fabs(m[1][i] * p.y) + std::fabs(m[2][i] * p.z) + std::fabs(m[3][i]);
    const float carried =
        std::fabs(m[0][i]) * p_error.x + std::fabs(m[1][i]) * p_error.y + std::fabs(m[2][i]) * p_error.z;
    e[i] = float_gamma(3) * magnitude + (1.0f + float_gamma(3)) * carried;
  }
  return e;
}

}  // namespace rt
