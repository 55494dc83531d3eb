// Rectangular area light, the proposal's rectangle (corner C, width W, height H) given as a corner
// and two edge vectors so that it can face any way: its points are corner + s edge1 + t edge2,
// s, t in [0, 1]. It emits towards normalize(edge1 x edge2) (and both ways if two_sided).
//
// One emission, `color`, read by each integrator by its own rule (docs/rendering.md, "Lights and units"):
//  - Seen directly (camera, mirror and glossy rays, and BSDF rays of the path tracer), its face
//    shows `color`: the radiance it emits, in both integrators.
//  - The path tracer samples its face as the area emitter it is: a point y seen from x at
//    distance d adds color x cos(theta_y) x cos(theta_x) x area / d^2, the physical rule.
//  - Whitted lights a point as its samples would as point lights: each sends
//    color x attenuation(d) x cos(theta_y) (theta_y between the light's normal and the direction
//    to x; |cos| when two-sided), so a small rect light facing a point lights it as a point light
//    of the same colour and attenuation would. A Blender area light sets `attenuation` so that
//    this matches its power (io/gltf/extras.cpp).
#pragma once

#include "core/lights/attenuation.h"
#include "core/ray.h"

namespace rt {

struct RectLight {
  Vec3 corner{0.0f};
  Vec3 edge1{1.0f, 0.0f, 0.0f};
  Vec3 edge2{0.0f, 0.0f, 1.0f};
  Vec3 color{1.0f};         // the radiance of its face: linear RGB, already multiplied by the scene's "intensity"
  Attenuation attenuation;  // Whitted's
  bool two_sided = false;

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
