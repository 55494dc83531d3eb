// Warps from the unit square to points and directions, with their densities: what a path
// tracer's light and BSDF sampling and the camera's lens draw from. Densities of directions are
// per unit solid angle.
#pragma once

#include <cmath>

#include "core/math.h"

namespace rt {

// (cos x, sin x) for x in [-pi/4, pi/4]: the minimax polynomials that Cephes' cosf and sinf use on
// that range, within 2 ulp of std::cos and std::sin there, without their range reduction (the
// library's sincosf was 3% of the Cornell box's path-traced time).
inline Vec2 cos_sin_quarter(float x) {
  const float x2 = x * x;
  const float s = x + x * x2 * (-1.6666654611e-1f + x2 * (8.3321608736e-3f + x2 * -1.9515295891e-4f));
  const float c =
      1.0f - 0.5f * x2 + x2 * x2 * (4.166664568298827e-2f + x2 * (-1.388731625493765e-3f + x2 * 2.443315711809948e-5f));
  return Vec2(c, s);
}

// Uniform point of the unit disk (Shirley and Chiu's concentric mapping, which keeps strata
// compact). The angle is pi/4 times a ratio within [-1, 1], measured from the x axis (|a| > |b|)
// or the y axis: cos_sin_quarter's range, the two swapped for the y axis (cos(pi/2 - t) = sin t).
inline Vec2 concentric_disk(Vec2 u) {
  const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return Vec2(0.0f);
  const bool wide = std::fabs(a) > std::fabs(b);
  const float radius = wide ? a : b;
  const Vec2 cs = cos_sin_quarter((kPi / 4.0f) * (wide ? b / a : a / b));
  return radius * (wide ? cs : Vec2(cs.y, cs.x));
}

// Cosine-weighted direction about +z (Malley's method): density cos(theta) / pi.
inline Vec3 cosine_hemisphere(Vec2 u) {
  const Vec2 d = concentric_disk(u);
  return Vec3(d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y)));
}

// Uniform direction over the whole sphere: density 1 / (4 pi).
inline Vec3 uniform_sphere(Vec2 u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}
inline constexpr float kUniformSpherePdf = 1.0f / (4.0f * kPi);

// Uniform point of a triangle as barycentrics (b1, b2) of its vertices 1 and 2 (the square-root
// warp: density 1 / area).
inline Vec2 uniform_triangle(Vec2 u) {
  const float s = std::sqrt(u.x);
  return Vec2(s * (1.0f - u.y), s * u.y);
}

// Veach's power heuristic (beta = 2): the weight of a sample drawn with density `a` when
// another strategy could have drawn it with density `b`.
inline float power_heuristic(float a, float b) {
  if (a == kInfinity) return 1.0f;
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

// An orthonormal frame about a unit normal: directions to and from local coordinates, z = n.
struct ShadingFrame {
  Vec3 t{1.0f, 0.0f, 0.0f}, b{0.0f, 1.0f, 0.0f}, n{0.0f, 0.0f, 1.0f};

  ShadingFrame() = default;
  explicit ShadingFrame(Vec3 normal) : n(normal) { orthonormal_basis(normal, t, b); }
  // x along `tangent` made perpendicular to the unit normal (an anisotropic lobe's direction);
  // any frame when the tangent is (nearly) along the normal.
  ShadingFrame(Vec3 normal, Vec3 tangent) : n(normal) {
    const Vec3 along = tangent - normal * glm::dot(normal, tangent);
    const float length2 = glm::dot(along, along);
    if (!(length2 > 1e-12f)) {
      orthonormal_basis(normal, t, b);
      return;
    }
    t = along / std::sqrt(length2);
    b = glm::cross(normal, t);
  }
  Vec3 to_local(Vec3 v) const { return Vec3(glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)); }
  Vec3 to_world(Vec3 v) const { return v.x * t + v.y * b + v.z * n; }
};

}  // namespace rt
