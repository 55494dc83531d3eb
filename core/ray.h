// A ray with the parametric interval [tmin, tmax] it may be hit in. Intersection routines
// narrow tmax as they find closer hits, so the interval is also the "closest so far".
#pragma once

#include "core/math.h"

namespace rt {

struct Ray {
  Vec3 origin{0.0f};
  Vec3 direction{0.0f, 0.0f, -1.0f};  // not necessarily unit length
  float tmin = 0.0f;
  float tmax = kInfinity;

  Vec3 at(float t) const { return origin + t * direction; }
};

// Shadow-acne rule used for every secondary ray: start the ray a small distance off the
// surface along the geometric normal, on the side the ray leaves towards. The distance
// scales with the magnitude of the hit point because float spacing does:
//   offset = kRayOffsetScale * max(1, max|p_i|).
// 1e-4 is ~1000 float ulps at |p| = 1: far above the intersection error of our routines,
// far below anything visible (a contact gap of 0.1 mm in a scene measured in metres).
inline constexpr float kRayOffsetScale = 1e-4f;

inline float ray_offset_distance(Vec3 p) { return kRayOffsetScale * std::max(1.0f, max_abs_component(p)); }

inline Vec3 offset_ray_origin(Vec3 p, Vec3 geometric_normal, Vec3 direction) {
  const float d = ray_offset_distance(p);
  return glm::dot(direction, geometric_normal) >= 0.0f ? p + d * geometric_normal : p - d * geometric_normal;
}

}  // namespace rt
