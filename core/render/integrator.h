// Integrators turn a ray into radiance. They are an open, coarse-grained set (one virtual call
// per camera sample, never per primitive), chosen by name from render settings.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/name_table.h"
#include "core/render/aovs.h"
#include "core/render/ray_counters.h"
#include "core/render_settings.h"
#include "core/sampling.h"
#include "core/scene.h"

namespace rt {

// Per-thread state handed down a ray tree: counters, the camera sample's keyed numbers, its cone.
struct TraceContext {
  const Scene& scene;
  const RenderSettings& settings;
  RayCounters& counters;
  SampleStream samples;
  // The angle one pixel subtends at the camera: the spread of each camera ray's cone, whose width
  // where a ray meets a surface picks the mip level of its textures. 0: finest level everywhere.
  float pixel_spread = 0.0f;
  // The cone's width where camera rays start: 0 from a point (perspective), one pixel's width
  // for parallel rays (orthographic).
  float pixel_footprint = 0.0f;
  // The camera sample's layers (core/render/aovs.h) when the render asks for them, else null:
  // the integrator fills them where the camera ray meets its first surface, light or nothing
  // (record_first_hit), and no later hit of the sample touches them.
  Aovs* aovs = nullptr;
};

// The camera sample's layers from what its ray met first; nothing once recorded (or not asked).
inline void record_first_hit(TraceContext& ctx, Vec3 albedo, Vec3 normal, float distance, Vec3 emission) {
  if (!ctx.aovs) return;
  *ctx.aovs = Aovs{albedo, normal, distance, emission};
  ctx.aovs = nullptr;
}
// The camera ray met nothing: the layers keep their defaults (black, no normal, far away) but
// the background's radiance, all the colour there is.
inline void record_no_hit(TraceContext& ctx, Vec3 background) {
  if (ctx.aovs) ctx.aovs->emission = background;
  ctx.aovs = nullptr;
}

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Radiance arriving along `ray`; depth = number of bounces already taken.
  Vec3 radiance(const Ray& ray, int depth, TraceContext& ctx) const {
    Ray r = ray;
    SceneHit met;
    ctx.scene.intersect(r, met);
    return radiance_from_hit(r, met, depth, ctx);
  }
  // The same for a ray whose first meeting is already known: `met` and ray.tmax as
  // Scene::intersect leaves them (camera rays, found a packet at a time).
  virtual Vec3 radiance_from_hit(const Ray& ray, const SceneHit& met, int depth, TraceContext& ctx) const = 0;
  // radiance_from_hit (depth 0) for count <= kPacketSize camera rays found together (a
  // CameraBatch), each with its own context (one thread's: the same scene and counters): out[i]
  // for rays[i]. Each gets what it would alone; an integrator may share work between them
  // (Whitted: the point lights' shadow rays, as packets).
  virtual void radiance_from_hits(const Ray* rays, const SceneHit* met, int count, TraceContext* const* ctx,
                                  Vec3* out) const {
    for (int i = 0; i < count; ++i) out[i] = radiance_from_hit(rays[i], met[i], 0, *ctx[i]);
  }
};

// What an integrator's name stands for in the name table.
struct IntegratorKind {
  std::unique_ptr<Integrator> (*make)();
  bool shows_radiance;  // false: a debug view (integrator_shows_radiance)
  bool samples_pixels;  // integrator_samples_pixels
};
// The name table: render.integrator and --integrator.
const NameTable<IntegratorKind>& integrators();

// The integrator registered under `name`, or nullptr if there is none.
std::unique_ptr<Integrator> make_integrator(std::string_view name);
// Whether the integrator registered under `name` makes radiance, which goes to the display
// through exposure and the tone curve (core/tone_map.h), rather than a debug view's data
// (normals, uv, depth, albedo), which is shown as it is.
bool integrator_shows_radiance(std::string_view name);
// Whether the integrator registered under `name` takes its own samples per pixel (the path
// tracer: render.samples_per_pixel, core/render/path_sampler.h) rather than render.antialias's.
bool integrator_samples_pixels(std::string_view name);

}  // namespace rt
