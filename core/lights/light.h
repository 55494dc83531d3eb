// The scene's lights are a closed set, dispatched statically: point, spot and directional lights
// (deltas: one shadow ray, hard shadows) and rectangular area lights (soft shadows). Each answers
// the light sampling interface: sample_li draws a direction towards it from a point, pdf_li gives
// the density with which sample_li draws a direction that a ray found by other means (a BSDF
// sample) met it along. Emissive surfaces (core/lights/emitters.h) and the sky
// (core/lights/environment.h) answer the same two questions.
#pragma once

#include <algorithm>
#include <cmath>
#include <variant>

#include "core/lights/directional_light.h"
#include "core/lights/light_sample.h"
#include "core/lights/point_light.h"
#include "core/lights/rect_light.h"
#include "core/lights/spot_light.h"

namespace rt {

using Light = std::variant<PointLight, RectLight, SpotLight, DirectionalLight>;

// u in [0, 1)^2 picks the point on an area light; a delta light ignores it.
inline LightSample sample_li(const PointLight& light, Vec3 point, Vec2 /*u*/) {
  LightSample s = light_sample_towards(point, light.position, light.color);
  s.radiance *= light.attenuation(s.distance);
  s.pdf = 1.0f;
  s.delta = true;
  return s;
}

inline LightSample sample_li(const SpotLight& light, Vec3 point, Vec2 /*u*/) {
  LightSample s = light_sample_towards(point, light.position, light.color);
  s.radiance *= light.attenuation(s.distance) * light.cone(-s.direction);
  s.pdf = 1.0f;
  s.delta = true;
  return s;
}

inline LightSample sample_li(const DirectionalLight& light, Vec3 /*point*/, Vec2 /*u*/) {
  LightSample s;
  s.direction = -light.direction;
  s.distance = kInfinity;
  s.radiance = light.color;
  s.pdf = 1.0f;
  s.delta = true;
  return s;
}

// What sampling a rect light and meeting it need of its shape, worked out once for many samples
// and rays.
struct RectFrame {
  Vec3 normal_area{0.0f};  // edge1 x edge2: the normal, as long as the area
  float area = 0.0f;
  Vec3 unit_normal{0.0f};
  // The edges' dot products and their determinant: a point's coordinates along the edges, which
  // need not be perpendicular, are solved in the edges' basis (intersect_rect).
  float e11 = 0.0f, e12 = 0.0f, e22 = 0.0f, det = 0.0f;
  explicit RectFrame(const RectLight& light)
      : normal_area(glm::cross(light.edge1, light.edge2)),
        area(glm::length(normal_area)),
        unit_normal(glm::normalize(normal_area)),
        e11(glm::dot(light.edge1, light.edge1)),
        e12(glm::dot(light.edge1, light.edge2)),
        e22(glm::dot(light.edge2, light.edge2)),
        det(e11 * e22 - e12 * e12) {}
};

// Where the ray meets the rectangle's face that shows light, in (ray.tmin, ray.tmax), and the
// point's coordinates along the edges (each in [0, 1]); false if it misses it or meets the dark
// back of a one-sided light.
inline bool intersect_rect(const RectLight& light, const RectFrame& frame, const Ray& ray, float& t,
                           Vec2* along = nullptr) {
  const float facing = glm::dot(ray.direction, frame.normal_area);
  if (facing == 0.0f || (!light.two_sided && facing > 0.0f)) return false;
  t = glm::dot(light.corner - ray.origin, frame.normal_area) / facing;
  if (!(t > ray.tmin && t < ray.tmax)) return false;
  const Vec3 q = ray.at(t) - light.corner;
  const float q1 = glm::dot(q, light.edge1), q2 = glm::dot(q, light.edge2);
  const float s = (q1 * frame.e22 - q2 * frame.e12) / frame.det, u = (q2 * frame.e11 - q1 * frame.e12) / frame.det;
  if (along) *along = Vec2(s, u);
  return s >= 0.0f && s <= 1.0f && u >= 0.0f && u <= 1.0f;
}
inline bool intersect_rect(const RectLight& light, const Ray& ray, float& t, Vec2* along = nullptr) {
  return intersect_rect(light, RectFrame(light), ray, t, along);
}

// A point of the rectangle drawn uniformly by area: density d^2 / (cos_light area) per solid
// angle, carrying the face's radiance towards the point (RectLight::lighting_radiance). (The cosine is worked out
// twice, from the unit normal for cos_light and from the area-long normal for the density, as Whitted and the path
// tracer always have: one formula for both moved a few pixels of the shipped turntable by one level.)
//
// rect_point is the sample without its density, all Whitted reads (its rule needs no pdf; its
// radiance is `color`, which Whitted scales by attenuation and cos_light): `to` runs from the
// shading point to the light's point.
inline LightSample rect_point(const RectLight& light, const RectFrame& frame, Vec3 to) {
  LightSample s;
  s.distance = std::sqrt(glm::dot(to, to));
  if (!(s.distance > 0.0f)) return s;  // on the light itself
  s.direction = to / s.distance;
  s.radiance = light.color;
  const float facing = -glm::dot(s.direction, frame.unit_normal);
  s.cos_light = light.two_sided ? std::fabs(facing) : std::max(0.0f, facing);  // 0 behind it
  return s;
}

inline LightSample sample_li(const RectLight& light, const RectFrame& frame, Vec3 point, Vec2 u) {
  const Vec3 to = light.point(u) - point;
  LightSample s = rect_point(light, frame, to);
  const float d2 = glm::dot(to, to);
  if (!(d2 > 0.0f)) return s;  // pdf 0
  float cos_light = -glm::dot(s.direction, frame.normal_area) / frame.area;
  if (light.two_sided) cos_light = std::fabs(cos_light);
  if (cos_light > 0.0f) s.pdf = d2 / (cos_light * frame.area);  // else its dark back, or edge-on: pdf 0
  s.radiance = light.lighting_radiance(s.distance, frame.area);
  return s;
}

inline LightSample sample_li(const RectLight& light, Vec3 point, Vec2 u) {
  return sample_li(light, RectFrame(light), point, u);
}

inline LightSample sample_li(const Light& light, Vec3 point, Vec2 u) {
  return std::visit([&](const auto& l) { return sample_li(l, point, u); }, light);
}

// The density of sample_li(light, point, u) for the direction `direction` (unit) that meets the
// light's face `distance` away from `point`.
inline float pdf_li(const RectFrame& frame, Vec3 direction, float distance) {
  const float cos_light = std::fabs(glm::dot(direction, frame.normal_area)) / frame.area;
  return distance * distance / (cos_light * frame.area);
}
inline float pdf_li(const RectLight& light, Vec3 direction, float distance) {
  return pdf_li(RectFrame(light), direction, distance);
}

inline bool is_delta(const Light& light) { return !std::holds_alternative<RectLight>(light); }

// How many shadow samples Whitted takes of a light: one of a delta light, shadow_samples of an
// area light.
inline int light_sample_count(const Light& light, int shadow_samples) { return is_delta(light) ? 1 : shadow_samples; }

}  // namespace rt
