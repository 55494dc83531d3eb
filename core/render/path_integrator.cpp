#include "core/render/path_integrator.h"

#include "core/render/direct_lighting.h"
#include "core/render/medium_stack.h"
#include "core/render/scene_lights.h"

namespace rt {
namespace {

// The ray cone's spread after a smooth (diffuse or glossy) bounce: such rays scatter widely, and
// their hits only need a coarse texture level (a fine one is as right, and slower).
constexpr float kScatteredSpread = 0.05f;

// A shadow ray from the surface to a point `distance` away along unit `direction`; false when
// something blocks it. Stops just short of the point, so the surface the point lies on does not.
bool visible(const EvaluatedSurface& s, Vec3 direction, float distance, TraceContext& ctx) {
  Ray shadow;
  shadow.origin = shadow_ray_origin(s, direction);
  shadow.direction = direction;
  shadow.tmin = 0.0f;
  shadow.tmax = distance * (1.0f - kShadowEpsilon);
  ++ctx.counters[RayKind::kShadow];
  return !ctx.scene.occluded(shadow);
}

// The MIS weight of a light sample (density light_pdf) that BSDF sampling finds with bsdf_pdf.
float light_weight(PathSettings::Strategy strategy, float light_pdf, float bsdf_pdf) {
  return strategy == PathSettings::Strategy::kLights ? 1.0f : power_heuristic(light_pdf, bsdf_pdf);
}
// The MIS weight of a light met by a BSDF-sampled ray, which light sampling finds with light_pdf.
float bsdf_weight(PathSettings::Strategy strategy, float bsdf_pdf, float light_pdf) {
  if (strategy == PathSettings::Strategy::kBsdf) return 1.0f;
  if (strategy == PathSettings::Strategy::kLights) return 0.0f;
  return power_heuristic(bsdf_pdf, light_pdf);
}

}  // namespace

// One shadow ray to each light of the scene's list (core/render/scene_lights.h), or with many
// lights to one drawn by power (scene.light_selection, its estimate divided by the light's
// probability): a delta light counts fully, a light that BSDF rays can also meet is weighted
// against them (MIS, its density times the probability of drawing it).
Vec3 PathIntegrator::direct_light(const EvaluatedSurface& s, const Bsdf& bsdf, int bounce, TraceContext& ctx) const {
  const Scene& scene = ctx.scene;
  const uint64_t path = static_cast<uint64_t>(bounce);
  const PathSettings::Strategy strategy = ctx.settings.path.strategy;
  const bool sample_areas = strategy != PathSettings::Strategy::kBsdf;  // all but the delta lights
  const auto one_light = [&](size_t l, float chosen) {
    if (!light_present(scene, l) || (!sample_areas && !light_is_delta(scene, l))) return Vec3(0.0f);
    const LightSample ls = sample_li(scene, l, s.position, ctx.samples, path, ctx.settings.detail);
    if (!(ls.pdf > 0.0f) || max_component(ls.radiance) <= 0.0f) return Vec3(0.0f);
    // An area light's sample is weighted against BSDF sampling's density: with f, in one go.
    float bsdf_pdf = 0.0f;
    const Vec3 f = ls.delta ? bsdf.eval(ls.direction) : bsdf.eval(ls.direction, bsdf_pdf);
    if (max_component(f) <= 0.0f) return Vec3(0.0f);
    if (!visible(s, ls.direction, ls.distance, ctx)) return Vec3(0.0f);
    if (ls.delta) return f * ls.radiance * (kDeltaLightScale / chosen);
    const float pdf = ls.pdf * chosen;
    return f * ls.radiance * (light_weight(strategy, pdf, bsdf_pdf) / pdf);
  };
  const LightSelection& selection = scene.light_selection;
  if (selection.active()) {
    float chosen = 1.0f;
    const float u = ctx.samples.get1(SamplePurpose::kLight, path, light_dimension(light_count(scene)));
    const size_t l = selection.sample(u, chosen);
    return one_light(l, chosen);
  }
  Vec3 sum(0.0f);
  for (size_t l = 0; l < light_count(scene); ++l) sum += one_light(l, 1.0f);
  return sum;
}

Vec3 PathIntegrator::radiance_from_hit(const Ray& camera_ray, const SceneHit& first, int, TraceContext& ctx) const {
  const Scene& scene = ctx.scene;
  const RenderSettings& settings = ctx.settings;
  Vec3 radiance(0.0f);
  Vec3 beta(1.0f);  // the path's throughput so far
  Ray ray = camera_ray;
  SceneHit met = first;
  MediumStack media;
  bool delta = true;      // the last bounce was a delta lobe (or the camera): what it meets counts fully
  float bsdf_pdf = 0.0f;  // the density of the last bounce's direction, for MIS where it meets a light
  float cone_width = ctx.pixel_footprint, cone_spread = ctx.pixel_spread;
  float travelled = 0.0f;   // along the path before this segment: the layers' distance (record below)
  float wavelength = 0.0f;  // > 0 once the path has met dispersive glass (materials/dispersion.h)
  for (int bounce = 0;; ++bounce) {
    const float length = glm::length(ray.direction);
    const Vec3 dir = ray.direction / length;
    const float distance = ray.tmax * length;
    // Beer-Lambert along the segment just travelled, inside the innermost medium.
    if (!media.empty()) {
      const Material& m = scene.materials()[media.innermost()];
      for (int c = 0; c < 3; ++c)
        if (m.absorption[c] > 0.0f) beta[c] *= std::exp(-m.absorption[c] * distance);
    }
    if (!met.surface && !met.light) {  // into the background: a uniform colour or an HDR image
      const Environment& sky = scene.background;
      const Vec3 sky_radiance = sky.radiance(dir);
      record_no_hit(ctx, beta * sky_radiance);
      float weight = 1.0f;
      if (!delta && sky.is_image())
        weight = bsdf_weight(settings.path.strategy, bsdf_pdf,
                             sky.pdf(dir) * scene.light_selection.probability(scene.lights.size() + 1));
      radiance += beta * sky_radiance * weight;
      break;
    }
    if (met.light) {
      const RectLight& rect = *met.light;
      record_first_hit(ctx, Vec3(0.0f), rect.normal(), travelled + distance, beta * rect.color);
      // A camera or mirror ray sees the face's colour, as Whitted shows it; a BSDF ray meets the
      // radiance the light samples carry (core/lights/rect_light.h), weighted against them.
      if (delta) {
        radiance += beta * rect.color;
      } else {
        const RectFrame frame(rect);  // a light met by a ray is rare enough to work it out
        const float chosen =
            scene.light_selection.active() ? scene.light_selection.probability(light_index(scene, rect)) : 1.0f;
        const float weight = bsdf_weight(settings.path.strategy, bsdf_pdf, pdf_li(frame, dir, distance) * chosen);
        radiance += beta * rect.lighting_radiance(distance, frame.area) * weight;
      }
      break;
    }
    const SurfaceInteraction si = scene.surface(ray, met.hit);
    const Material& material = scene.materials()[si.material];
    cone_width += cone_spread * distance;
    const EvaluatedSurface s =
        evaluate_surface(material, si, ray.direction, scene.textures(), cone_width, settings.detail);
    // The layers come from the first surface that is not a perfect mirror or clear glass (seen
    // through those, tinted by them: as Cycles' and OpenImageDenoise's denoising albedo), so
    // that a denoiser keeps what a glass ball or a mirror shows sharp.
    const auto record = [&] { record_first_hit(ctx, beta * s.diffuse, s.n, travelled + distance, beta * s.emission); };
    if (ctx.aovs && bounce >= settings.max_depth) [[unlikely]]
      record();
    if (s.emission != Vec3(0.0f)) {
      float weight = 1.0f;
      const float light_pdf = delta ? 0.0f
                                    : surface_pdf_li(scene, met.hit, si.geometric_normal, dir, distance) *
                                          scene.light_selection.probability(scene.lights.size());
      if (light_pdf > 0.0f) weight = bsdf_weight(settings.path.strategy, bsdf_pdf, light_pdf);
      radiance += beta * s.emission * weight;
    }
    if (bounce >= settings.max_depth) break;

    // The indices on both sides, by the medium stack's rule (as Whitted's refraction).
    float eta = 1.0f;
    MediumStack beyond = media;
    if (s.transmissive()) {
      if (wavelength == 0.0f && scene.materials()[s.medium].pbr.layers.dispersion > 0.0f) {
        // Dispersive glass: the path goes on at one wavelength, weighted by its colour.
        wavelength = wavelength_from(ctx.samples.get1(SamplePurpose::kWavelength, 0, 0));
        beta *= wavelength_weight(wavelength);
      }
      const MediumCrossing crossing = cross_medium(media, s.medium, s.entering, scene.materials(), wavelength);
      beyond = crossing.beyond;
      eta = crossing.n_after / crossing.n_before;
    }
    const Bsdf bsdf(s, eta);
    if (ctx.aovs && bsdf.has_smooth_lobes()) [[unlikely]]
      record();
    if (bsdf.has_smooth_lobes()) radiance += beta * direct_light(s, bsdf, bounce, ctx);

    const float pick = ctx.samples.get1(SamplePurpose::kBsdf, static_cast<uint64_t>(bounce), 0);
    const Vec2 u = ctx.samples.get2(SamplePurpose::kBsdf, static_cast<uint64_t>(bounce), 1);
    BsdfSample b;
    if (!bsdf.sample(pick, u, b)) break;
    beta *= b.weight;
    delta = b.delta;
    bsdf_pdf = b.pdf;
    if (b.transmitted) media = beyond;
    if (!delta) cone_spread = std::max(cone_spread, kScatteredSpread);
    if (bounce + 1 >= kRouletteStart) {
      // Survive with a probability that follows the throughput, and make up for the paths ended.
      // Cycles' rule: the square root of its largest channel, which ends dim paths later than the
      // channel itself would (their light still shows after the view transform's curve).
      const float survive = std::sqrt(max_component(beta));
      if (survive < 1.0f) {
        if (ctx.samples.get1(SamplePurpose::kRoulette, static_cast<uint64_t>(bounce), 0) >= survive) break;
        beta /= survive;
      }
    }
    if (!(max_component(beta) > 0.0f) || !is_finite(beta)) break;

    travelled += distance;
    ray = Ray{};
    ray.origin = offset_ray_origin(s.position, s.position_error, s.ng, b.wi);
    ray.direction = b.wi;
    ++ctx.counters[RayKind::kBounce];
    // Into the surface's own primitive (through it from outside, or reflected on its inside): a
    // closed shape's neighbours answer without the walk (Bvh::intersect_from_inside). Out of it,
    // on the side it came from when it came from outside (a shading normal can send a sampled
    // direction the other way): the shape is not tested (Bvh::intersect_leaving).
    const bool outwards = (glm::dot(b.wi, s.ng) > 0.0f) == s.entering;
    const RayStart from = b.transmitted == s.entering ? RayStart{met.hit.prim, true}
                          : outwards                  ? RayStart{met.hit.prim, false}
                                                      : RayStart{};
    met = SceneHit{};
    scene.intersect(ray, met, from);
  }
  return radiance;
}

}  // namespace rt
