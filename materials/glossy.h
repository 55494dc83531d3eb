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
  const Vec3 a = glm::abs(r);
  if (a.x <= a.y && a.x <= a.z) u = Vec3(0.0f, -r.z, r.y);
  else if (a.y <= a.z) u = Vec3(-r.z, 0.0f, r.x);
  else u = Vec3(-r.y, r.x, 0.0f);
  u = glm::normalize(u);
  v = glm::cross(r, u);
}

// How n glossy rays are stratified over the square: a rows x cols grid, one jittered sample per
// cell. n = 4, 9, 16, 64 give sqrt(n) x sqrt(n); other counts the squarest grid with enough
// cells (8 -> 2 x 4; 7 -> 2 x 4 with one cell unused).
struct GlossyGrid {
  int rows = 1, cols = 1;
};
inline GlossyGrid glossy_grid(int n) {
  GlossyGrid g;
  g.rows = std::max(1, static_cast<int>(std::sqrt(static_cast<float>(n)) + 1e-4f));
  g.cols = (n + g.rows - 1) / g.rows;
  return g;
}

// Sample `index` of the grid, jittered by (jx, jy) in [0, 1)^2: a point of the unit square.
inline Vec2 glossy_grid_point(const GlossyGrid& g, int index, float jx, float jy) {
  const int row = index / g.cols, col = index % g.cols;
  return Vec2((static_cast<float>(col) + jx) / static_cast<float>(g.cols),
              (static_cast<float>(row) + jy) / static_cast<float>(g.rows));
}

// The perturbed direction for unit-square point p (p = (0.5, 0.5) is the mirror direction).
inline Vec3 glossy_direction(Vec3 r, Vec3 u, Vec3 v, float width, Vec2 p) {
  return glm::normalize(r + width * (p.x - 0.5f) * u + width * (p.y - 0.5f) * v);
}

}  // namespace rt
