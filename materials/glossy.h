// The proposal's glossy reflection: instead of the one mirror ray r, several rays through points
// of a square of width `a` centred on r's tip and perpendicular to it,
//   r' = normalize(r + (s - a/2) u + (t - a/2) v),  s, t in [0, a),
// with u, v an orthonormal pair perpendicular to r. Wider squares blur more.
#pragma once

#include <cmath>

#include "core/math.h"

namespace rt {

// Hughes and Moller, "Building an Orthonormal Basis from a Unit Vector" (JGT 1999): zero the
// component of r smallest in magnitude, swap the other two and negate one; that is perpendicular
// to r and never short, since the two kept components hold most of r's length.
inline void hughes_moller_basis(Vec3 r, Vec3& u, Vec3& v) {
  const Vec3 a = abs3(r);
  if (a.x <= a.y && a.x <= a.z) u = Vec3(0.0f, -r.z, r.y);
  else if (a.y <= a.z) u = Vec3(-r.z, 0.0f, r.x);
  else u = Vec3(-r.y, r.x, 0.0f);
  u = glm::normalize(u);
  v = glm::cross(r, u);
}

// The rays are stratified with core/sampling.h's StratifiedGrid.

// The perturbed direction for unit-square point p (p = (0.5, 0.5) is the mirror direction).
inline Vec3 glossy_direction(Vec3 r, Vec3 u, Vec3 v, float width, Vec2 p) {
  return glm::normalize(r + width * (p.x - 0.5f) * u + width * (p.y - 0.5f) * v);
}

}  // namespace rt
