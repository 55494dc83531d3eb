// The optics of a smooth surface: mirror reflection, refraction by Snell's law and the Fresnel
// split by Schlick's approximation. Directions are unit vectors; d points at the surface, n is
// the unit normal on the side d comes from (dot(d, n) < 0).
#pragma once

#include "core/math.h"

namespace rt {

// Mirror direction: r = d - 2 (d.n) n. (Works for n on either side.)
inline Vec3 reflect(Vec3 d, Vec3 n) { return d - 2.0f * glm::dot(d, n) * n; }

// Refracted direction through an interface with relative index eta = n_incident / n_transmitted,
// of unit length for unit d and n.
// Snell: sin(theta_t) = eta sin(theta_i). Returns false, leaving `t` untouched, on total internal
// reflection (eta sin(theta_i) > 1).
inline bool refract(Vec3 d, Vec3 n, float eta, Vec3& t) {
  const float cos_i = -glm::dot(d, n);
  const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
  if (sin2_t > 1.0f) return false;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  // Of unit length already, for unit d and n (|t|^2 = eta^2 sin^2_i + cos^2_t = 1): normalised
  // again, a square root and a division sat on the path from one hit to the next
  // (refraction.json 0.99x the time without them).
  t = eta * d + (eta * cos_i - cos_t) * n;
  return true;
}

// Fraction of light reflected at an interface from index n1 (incident side) into n2, for the
// incident cosine cos_i, by Schlick: R = R0 + (1 - R0)(1 - cos)^5 with R0 = ((n1 - n2)/(n1 + n2))^2.
// Leaving a denser medium (n1 > n2) the cosine is the transmitted one (Schlick's rule: the cosine
// on the less dense side), and beyond the critical angle everything is reflected (returns 1).
// Equal indices are no interface at all: 0, where the bare formula would still reflect at grazing.
inline float schlick_reflectance(float cos_i, float n1, float n2) {
  if (n1 == n2) return 0.0f;
  float cos = std::clamp(cos_i, 0.0f, 1.0f);
  if (n1 > n2) {
    const float eta = n1 / n2;
    const float sin2_t = eta * eta * (1.0f - cos * cos);
    if (sin2_t >= 1.0f) return 1.0f;
    cos = std::sqrt(1.0f - sin2_t);
  }
  const float r0 = (n1 - n2) / (n1 + n2);
  const float m = 1.0f - cos;
  return r0 * r0 + (1.0f - r0 * r0) * (m * m) * (m * m) * m;
}

}  // namespace rt
