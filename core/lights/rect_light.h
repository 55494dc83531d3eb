// Rectangular area light, the proposal's rectangle (corner C, width W, height H) given as a corner
// and two edge vectors so that it can face any way: its points are corner + s edge1 + t edge2,
// s, t in [0, 1]. It emits towards normalize(edge1 x edge2) (and both ways if two_sided).
//
// It lights like its point samples: a point y of it, seen from x at distance d, sends
//   colour * attenuation(d) * max(0, cos theta_y)
// (theta_y between its normal and the direction to x; |cos| when two-sided), so a small rect
// light facing a point lights it as a point light of the same colour and intensity would. Seen
// directly (camera, reflection and glossy rays), its face shows colour: its emitted radiance.
#pragma once

#include "core/lights/attenuation.h"
#include "core/ray.h"

namespace rt {

struct RectLight {
  Vec3 corner{0.0f};
  Vec3 edge1{1.0f, 0.0f, 0.0f};
  Vec3 edge2{0.0f, 0.0f, 1.0f};
  Vec3 color{1.0f};  // linear RGB, already multiplied by the scene's "intensity"
  Attenuation attenuation;
  bool two_sided = false;
  // The radiance of its face as the path tracer's area emitter. A scene file's rect light
  // emits its colour (what Whitted shows on its face); one from a Blender area light of power P
  // emits P / (4 A) x its colour, as Cycles' does (tools/cycles measures it), where Whitted's
  // colour is set for its own rule (io/gltf/extras.cpp).
  Vec3 radiance{1.0f};

  // Unit normal, the side it emits towards: edge1 x edge2. (io refuses parallel or zero edges.)
  Vec3 normal() const { return glm::normalize(glm::cross(edge1, edge2)); }
  Vec3 point(Vec2 u) const { return corner + u.x * edge1 + u.y * edge2; }

  // Where the ray meets the rectangle's face that shows light, in (ray.tmin, ray.tmax), and the
  // point's coordinates along the edges (each in [0, 1]); false if it misses it or meets the dark
  // back of a one-sided light.
  bool intersect(const Ray& ray, float& t, Vec2* along = nullptr) const {
    const Vec3 n = glm::cross(edge1, edge2);
    const float facing = glm::dot(ray.direction, n);
    if (facing == 0.0f || (!two_sided && facing > 0.0f)) return false;
    t = glm::dot(corner - ray.origin, n) / facing;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    const Vec3 q = ray.at(t) - corner;
    // Coordinates along the edges, which need not be perpendicular: solve in the edges' basis.
    const float e11 = glm::dot(edge1, edge1), e12 = glm::dot(edge1, edge2), e22 = glm::dot(edge2, edge2);
    const float q1 = glm::dot(q, edge1), q2 = glm::dot(q, edge2);
    const float det = e11 * e22 - e12 * e12;
    const float s = (q1 * e22 - q2 * e12) / det, u = (q2 * e11 - q1 * e12) / det;
    if (along) *along = Vec2(s, u);
    return s >= 0.0f && s <= 1.0f && u >= 0.0f && u <= 1.0f;
  }
};

}  // namespace rt
