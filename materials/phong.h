// Phong reflection model, as in the proposal: for a light of radiance L in direction l,
//   L * (kd * max(0, n.l) + ks * max(0, r.v)^shininess),   r = 2 (n.l) n - l,
// with the specular term only where the light is in front of the surface (n.l > 0).
// No energy normalisation: kd and ks are the artist's weights, as in the classic model.
#pragma once

#include "materials/lobe_power.h"
#include "materials/optics.h"

namespace rt {

// The factor that multiplies a light's radiance: n, l (towards the light) and v (towards the
// viewer) are unit vectors; kd, ks and shininess as evaluated for this point.
inline Vec3 phong_reflectance(Vec3 kd, Vec3 ks, float shininess, Vec3 n, Vec3 l, Vec3 v) {
  const float n_dot_l = glm::dot(n, l);
  if (n_dot_l <= 0.0f) return Vec3(0.0f);
  Vec3 result = kd * n_dot_l;
  const float r_dot_v = glm::dot(reflect(-l, n), v);
  if (r_dot_v > 0.0f) result += ks * lobe_power(r_dot_v, shininess);
  return result;
}

}  // namespace rt
