// Phong reflection model, as in the proposal: for a light of radiance L in direction l,
//   L * (kd * max(0, n.l) + ks * max(0, r.v)^shininess),   r = 2 (n.l) n - l,
// with the specular term only where the light is in front of the surface (n.l > 0).
// No energy normalisation: kd and ks are the artist's weights, as in the classic model.
#pragma once

#include "core/material.h"

namespace rt {

// Mirror direction of incoming direction d (pointing at the surface) about unit normal n:
// r = d - 2 (d.n) n.
inline Vec3 reflect(Vec3 d, Vec3 n) { return d - 2.0f * glm::dot(d, n) * n; }

// The factor that multiplies a light's radiance: n, l (towards the light) and v (towards the
// viewer) are unit vectors.
inline Vec3 phong_reflectance(const Material& m, Vec3 n, Vec3 l, Vec3 v) {
  const float n_dot_l = glm::dot(n, l);
  if (n_dot_l <= 0.0f) return Vec3(0.0f);
  Vec3 result = m.kd * n_dot_l;
  const float r_dot_v = glm::dot(reflect(-l, n), v);
  if (r_dot_v > 0.0f) result += m.ks * std::pow(r_dot_v, m.shininess);
  return result;
}

}  // namespace rt
