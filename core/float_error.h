// Bounds on the rounding error of single-precision arithmetic, for robust ray origins (Pharr,
// Jakob and Humphreys, "Physically Based Rendering", 4th ed., section 6.8). A point carries an
// absolute error bound per component: the exact point lies within +-error of the computed one.
#pragma once

#include <bit>
#include <cstdint>

#include "core/affine_lanes.h"
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
// Written a column at a time (core/affine_lanes.h): row i of each vector is the sum for e[i].
inline Vec3 transformed_point_error(const Mat4& m, Vec3 p, Vec3 p_error) {
  const Float4 c0 = column4(m, 0), c1 = column4(m, 1), c2 = column4(m, 2);
  const Float4 magnitude = abs4(c0 * p.x) + abs4(c1 * p.y) + abs4(c2 * p.z) + abs4(column4(m, 3));
  const Float4 carried = abs4(c0) * p_error.x + abs4(c1) * p_error.y + abs4(c2) * p_error.z;
  return xyz(float_gamma(3) * magnitude + (1.0f + float_gamma(3)) * carried);
}

// The same for a point known exactly (p_error 0), the same floats: for a finite matrix (every
// Transform's, core/transform.h) the carried term is then +0, and x + 0 is x.
inline Vec3 transformed_point_error(const Mat4& m, Vec3 p) {
  const Float4 magnitude =
      abs4(column4(m, 0) * p.x) + abs4(column4(m, 1) * p.y) + abs4(column4(m, 2) * p.z) + abs4(column4(m, 3));
  return xyz(float_gamma(3) * magnitude);
}

}  // namespace rt
