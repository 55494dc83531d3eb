// The scene's lights in one list, as light sampling sees them: the scene's lights (point, spot,
// directional, rect) by their index, then its emissive surfaces as one light (a point drawn from
// the Emitters table: core/lights/emitters.h), then the sky (a direction drawn from an
// environment image by luminance). Each answers sample_li; the pdf_li functions give the
// density of whatever a BSDF ray met, for multiple importance sampling. The path tracer's
// direct light is one loop over this list (core/render/path_integrator.cpp).
//
// Light l's numbers are keyed (SamplePurpose::kLight, path, light_dimension(l, i)), as Whitted's
// shadow samples: the surfaces' point i = 0, their entry i = 1.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/lights/light_sample.h"
#include "core/render_settings.h"
#include "core/sampling.h"
#include "core/scene.h"

namespace rt {

// How many lights the list holds: the scene's, the surfaces and the sky (the last two draw
// nothing when the scene has no emissive surface or no environment image).
inline size_t light_count(const Scene& scene) { return scene.lights.size() + 2; }

// Whether light l has anything to draw: the surfaces' and the sky's slots are empty in a scene
// without emissive surfaces or an environment image (checked before sampling, which costs more).
inline bool light_present(const Scene& scene, size_t l) {
  const size_t n = scene.lights.size();
  return l < n || (l == n ? !scene.emitters.empty() : scene.background.is_image());
}

// The index in the list of the scene's rect light `rect` (met by a ray: Scene::intersect).
inline size_t light_index(const Scene& scene, const RectLight& rect) {
  for (size_t l = 0; l < scene.lights.size(); ++l)
    if (std::get_if<RectLight>(&scene.lights[l]) == &rect) return l;
  return scene.lights.size();
}

// Whether light l is a delta light (no ray meets it by chance: light sampling alone finds it).
inline bool light_is_delta(const Scene& scene, size_t l) {
  return l < scene.lights.size() && is_delta(scene.lights[l]);
}

// The emissive surfaces' and the sky's samples (l >= scene.lights.size()), out of line; `sample`
// numbers several samples of one shading point (Whitted's shadow samples; the path tracer's one is 0).
LightSample sample_area_li(const Scene& scene, size_t l, Vec3 point, const SampleStream& samples, uint64_t path,
                           SurfaceDetailSwitches detail, uint32_t sample = 0);

// A sample of light l for the shading point `point`, from the numbers of `samples` at bounce
// `path`. pdf 0: none (nothing to draw, or a point the light does not emit from). Inline for the
// scene's lights: the path tracer asks once a light per bounce.
inline LightSample sample_li(const Scene& scene, size_t l, Vec3 point, const SampleStream& samples, uint64_t path,
                             SurfaceDetailSwitches detail) {
  if (l < scene.lights.size()) {
    // Only an area light reads its pair of numbers: a delta light's would be drawn for nothing
    // (each pair is hashed and scrambled: 3% of a path-traced scene with a sun and a lamp).
    if (const RectLight* rect = std::get_if<RectLight>(&scene.lights[l]))
      return sample_li(*rect, scene.rect_frame(l), point,
                       samples.get2(SamplePurpose::kLight, path, light_dimension(l)));
    return sample_li(scene.lights[l], point, Vec2(0.0f));
  }
  return sample_area_li(scene, l, point, samples, path, detail);
}

// The density with which sample_li draws the direction `direction` (unit) from a point to the
// emissive surface of `hit`, met `distance` away with unit geometric normal `normal`; 0 when
// light sampling never draws that surface.
float surface_pdf_li(const Scene& scene, const Hit& hit, Vec3 normal, Vec3 direction, float distance);

}  // namespace rt
