// The shading stage: between the hit and the integrator. Scene::surface gives the geometry of a
// hit; evaluate_surface turns it and the hit's material into everything the integrator reads,
// with the normals turned to face the ray. Textures and bump maps plug in here: they will change
// kd or the shading frame at this point and nowhere else.
#pragma once

#include "core/hit.h"
#include "core/material.h"

namespace rt {

struct EvaluatedSurface {
  Vec3 position{0.0f};
  Vec3 n{0.0f, 0.0f, 1.0f};   // unit shading normal, on the side the ray came from
  Vec3 ng{0.0f, 0.0f, 1.0f};  // unit geometric normal, same side
  Vec3 wo{0.0f, 0.0f, 1.0f};  // unit, towards where the ray came from
  bool entering = true;       // the ray arrived from the outward side (for refraction)
  // Shading frame, as Scene::surface gave it.
  Vec2 uv{0.0f};
  Vec3 dpdu{1.0f, 0.0f, 0.0f};
  Vec3 dpdv{0.0f, 1.0f, 0.0f};
  // The material at this point.
  uint32_t material = 0;
  Vec3 diffuse{0.0f};  // kd x (1 - transmission): light that passes through is not also scattered
  Vec3 specular{0.0f};
  float shininess = 32.0f;
  Vec3 reflectivity{0.0f};
  Vec3 transmission{0.0f};
  float ior = 1.5f;
  Vec3 absorption{0.0f};
  float glossy = 0.0f;

  bool transmissive() const { return max_component(transmission) > 0.0f; }
};

// `ray_direction` is the direction of the ray that hit (any length).
inline EvaluatedSurface evaluate_surface(const Material& m, const SurfaceInteraction& si, Vec3 ray_direction) {
  EvaluatedSurface s;
  s.position = si.position;
  // Shade the side the ray sees: both sides of an opaque surface are lit like its front.
  const float side = si.front_face ? 1.0f : -1.0f;
  s.n = side * si.shading_normal;
  s.ng = side * si.geometric_normal;
  s.wo = -glm::normalize(ray_direction);
  s.entering = si.front_face;
  s.uv = si.uv;
  s.dpdu = si.dpdu;
  s.dpdv = si.dpdv;
  s.material = si.material;
  s.diffuse = m.kd * (Vec3(1.0f) - m.transmission);
  s.specular = m.ks;
  s.shininess = m.shininess;
  s.reflectivity = m.reflectivity;
  s.transmission = m.transmission;
  s.ior = m.ior;
  s.absorption = m.absorption;
  s.glossy = m.glossy;
  return s;
}

}  // namespace rt
