// glm's products of an affine Mat4 with a point or a vector, a column in one 4-lane vector
// (core/simd.h). Each lane does the operations of glm's own, in the same order, so the
// floats are the same; glm writes them a component at a time, which took four times the
// instructions (refraction.json: 4.5% fewer in all with these; docs/benchmark.md).
#pragma once

#include "core/math.h"
#include "core/simd.h"

namespace rt {

RT_SIMD_INLINE Float4 column4(const Mat4& m, int c) { return load4(&m[c][0]); }
RT_SIMD_INLINE Vec3 xyz(Float4 v) { return Vec3(v[0], v[1], v[2]); }

// Vec3(m * Vec4(p, 1)): glm's (m0 x + m1 y) + (m2 z + m3 w), with m3 w = m3 for w = 1.
RT_SIMD_INLINE Vec3 affine_point(const Mat4& m, Vec3 p) {
  return xyz((column4(m, 0) * p.x + column4(m, 1) * p.y) + (column4(m, 2) * p.z + column4(m, 3)));
}

// Mat3(m) * v: glm's (m0 x + m1 y) + m2 z.
RT_SIMD_INLINE Vec3 linear_vector(const Mat4& m, Vec3 v) {
  return xyz((column4(m, 0) * v.x + column4(m, 1) * v.y) + column4(m, 2) * v.z);
}

}  // namespace rt
