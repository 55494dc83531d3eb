// The Trowbridge-Reitz (GGX) microfacet distribution of glTF's reference BRDF, in a local frame
// whose z axis is the shading normal: D, Smith's masking G1 (glTF's separable form, G = G1(l)
// G1(v)) and Heitz's sampling of the normals a direction sees ("Sampling the GGX Distribution of
// Visible Normals", JCGT 2018). alpha = roughness^2, as glTF defines it; KHR_materials_anisotropy
// gives x (the frame's tangent) its own alpha, and the formulas are the anisotropic ones, which
// reduce to the isotropic ones when the two are equal.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace rt {

struct Ggx {
  float alpha_x = 1.0f, alpha_y = 1.0f;

  Ggx() = default;
  explicit Ggx(float alpha) : alpha_x(alpha), alpha_y(alpha) {}
  Ggx(float ax, float ay) : alpha_x(ax), alpha_y(ay) {}
  // The smaller alpha: what decides whether the lobe is sharp enough to be a mirror.
  float min_alpha() const { return std::min(alpha_x, alpha_y); }

  // Normal distribution: 1 / (pi ax ay ((hx/ax)^2 + (hy/ay)^2 + hz^2)^2) for h above the surface
  // (isotropic: alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)).
  float d(Vec3 h) const {
    if (h.z <= 0.0f) return 0.0f;
    const float x = h.x / alpha_x, y = h.y / alpha_y;
    const float k = x * x + y * y + h.z * h.z;
    return 1.0f / (kPi * alpha_x * alpha_y * k * k);
  }
  // Masking of direction w (w.z > 0): 2 cos / (cos + sqrt(cos^2 + ax^2 x^2 + ay^2 y^2)) (isotropic:
  // 2 cos / (cos + sqrt(alpha^2 + (1 - alpha^2) cos^2))).
  float g1(Vec3 w) const {
    const float c = w.z;
    if (c <= 0.0f) return 0.0f;
    const float x = alpha_x * w.x, y = alpha_y * w.y;
    return 2.0f * c / (c + std::sqrt(c * c + x * x + y * y));
  }
  // A microfacet normal seen from wo (wo.z > 0), with density d_visible(wo, h) = G1(wo) max(0,
  // wo.h) D(h) / wo.z: stretch to the unit-roughness configuration, sample the projected
  // hemisphere there, unstretch.
  Vec3 sample_visible(Vec3 wo, Vec2 u) const {
    const Vec3 vh = glm::normalize(Vec3(alpha_x * wo.x, alpha_y * wo.y, wo.z));
    const float len2 = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = len2 > 0.0f ? Vec3(-vh.y, vh.x, 0.0f) / std::sqrt(len2) : Vec3(1.0f, 0.0f, 0.0f);
    const Vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(Vec3(alpha_x * nh.x, alpha_y * nh.y, std::max(1e-6f, nh.z)));
  }
  // Density of the reflected direction wi = reflect(-wo, h) when h is drawn by sample_visible:
  // d_visible / (4 wo.h) = G1(wo) D(h) / (4 wo.z).
  float reflected_pdf(Vec3 wo, Vec3 h) const {
    if (wo.z <= 0.0f) return 0.0f;
    return g1(wo) * d(h) / (4.0f * wo.z);
  }
};

// Schlick's Fresnel with a colour at normal incidence (glTF: mix(0.04, base, metallic)).
inline Vec3 schlick_fresnel(Vec3 f0, float cos_theta) {
  const float m = std::clamp(1.0f - cos_theta, 0.0f, 1.0f);
  const float m5 = (m * m) * (m * m) * m;
  return f0 + (Vec3(1.0f) - f0) * m5;
}

// glTF's dielectric Fresnel term for the diffuse layer (F0 = 0.04).
inline float dielectric_schlick(float cos_theta) {
  const float m = std::clamp(1.0f - cos_theta, 0.0f, 1.0f);
  return 0.04f + 0.96f * (m * m) * (m * m) * m;
}

// Below this alpha (roughness ~0.03) GGX is a mirror for any purpose, and its density too sharp
// for float: the lobe becomes a delta.
inline constexpr float kSmoothAlpha = 1e-3f;

// Unpolarised Fresnel reflectance of a smooth dielectric interface for light arriving at cosine
// cos_i (>= 0) on the side of index n_i; eta = n_t / n_i. 1 beyond the critical angle.
inline float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  const float parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (parallel * parallel + perpendicular * perpendicular);
}

}  // namespace rt
