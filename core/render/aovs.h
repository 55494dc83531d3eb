// What the first surface a camera sample meets shows beside its colour: the layers an EXR output
// holds (--aov) and a denoiser or a live preview reads. (The path tracer records them at the
// first surface that is not a perfect mirror or clear glass, seen through those and tinted by
// them, as Cycles' and OpenImageDenoise's denoising layers: path_integrator.cpp.) The integrator that renders the
// colour fills them at its first hit (TraceContext::aovs), in the same pass; the pixel sampler averages them with the
// colour's weights (as pbrt-v4's GBufferFilm), but keeps the distance of the nearest surface any sample met (as
// Arnold's closest filter): an average of a near surface and the background's 1e10 is no distance at all.
#pragma once

#include <algorithm>

#include "core/math.h"

namespace rt {

struct Aovs {
  // Blender's depth where nothing is met.
  static constexpr float kFarAway = 1e10f;

  Vec3 albedo{0.0f};          // the diffuse colour (kd, less what the material transmits); 0 on a light's face
  Vec3 normal{0.0f};          // the shading normal, world space, bump and normal maps applied, facing the ray
  float distance = kFarAway;  // along the camera ray
  // What the first thing met sends back by itself (a light's face, an emissive surface, the
  // background): the part of the colour no bounce made, which a denoiser leaves as it is.
  Vec3 emission{0.0f};

  // Adds a sample's layers with `weight` (its share of the pixel), the distance the nearer.
  void add(const Aovs& sample, float weight) {
    albedo += weight * sample.albedo;
    normal += weight * sample.normal;
    distance = std::min(distance, sample.distance);
    emission += weight * sample.emission;
  }
};

}  // namespace rt
