// Rectangular area light, the proposal's rectangle (corner C, width W, height H) given as a corner
// and two edge vectors so that it can face any way: its points are corner + s edge1 + t edge2,
// s, t in [0, 1]. It emits towards normalize(edge1 x edge2) (and both ways if two_sided).
//
// One light unit for both integrators (docs/rendering.md, "Lights and units"): a point lights as
// the light's samples would as point lights, each sending color x attenuation(d) x cos(theta_y)
// (theta_y between the light's normal and the direction to the point, d its distance; |cos| when
// two-sided), averaged over the face. So a small rect light facing a point lights it as a point
// light of the same colour and attenuation would, in Whitted and in the path tracer alike.
//  - Whitted takes that rule as it is, over render.shadow_samples stratified points.
//  - The path tracer needs the face's radiance, which that rule makes
//    L(d) = pi x color x attenuation(d) x d^2 / area (lighting_radiance): what its light samples
//    carry and what its BSDF rays meet. With attenuation (0, 0, pi / area), L is `color`: an
//    ordinary area emitter of that radiance (a Blender area light's import, io/gltf/extras.cpp).
//    (radiance_attenuation; a scene says "radiance": true).
//  - Seen by a camera or mirror ray (and by Whitted's glossy rays), the face shows `color`.
#pragma once

#include "core/lights/attenuation.h"
#include "core/math.h"
#include "core/ray.h"

namespace rt {

struct RectLight {
  Vec3 corner{0.0f};
  Vec3 edge1{1.0f, 0.0f, 0.0f};
  Vec3 edge2{0.0f, 0.0f, 1.0f};
  Vec3 color{1.0f};         // the radiance of its face: linear RGB, already multiplied by the scene's "intensity"
  Attenuation attenuation;  // Whitted's
  bool two_sided = false;
  // False: camera rays pass through its face (Blender's lights, which Cycles hides from the camera
  // unless Object > Visibility > Camera is on); reflections, refractions and bounces still meet it.
  bool camera_visible = true;

  // Unit normal, the side it emits towards: edge1 x edge2. (io refuses parallel or zero edges.)
  Vec3 normal() const { return glm::normalize(glm::cross(edge1, edge2)); }
  Vec3 point(Vec2 u) const { return corner + u.x * edge1 + u.y * edge2; }

  // The face's radiance towards a point `distance` away, by which the light lights it (the rule
  // above); `area` is the face's, |edge1 x edge2|.
  Vec3 lighting_radiance(float distance, float area) const {
    return color * (kPi * attenuation(distance) * distance * distance / area);
  }
};

// The attenuation under which a rect light's colour is the radiance of its face in both
// integrators: (0, 0, pi / area).
inline Attenuation radiance_attenuation(const RectLight& light) {
  return Attenuation{0.0f, 0.0f, kPi / glm::length(glm::cross(light.edge1, light.edge2))};
}

}  // namespace rt
