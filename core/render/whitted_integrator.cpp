#include "core/render/whitted_integrator.h"

#include <new>

#include "core/render/direct_lighting.h"
#include "core/storage_only.h"
#include "materials/glossy.h"
#include "materials/optics.h"

namespace rt {

// Inlined into trace(), the recursion's hot call: as a call of its own it cost glossy.json 2% (measured).
[[gnu::always_inline]] inline Vec3 WhittedIntegrator::shade(const Ray& ray, const SceneHit& met, const PathState& state,
                                                            TraceContext& ctx) const {
  if (!met.surface) return shade_no_surface(ray, met, state, ctx);
  float cone_width;
  const EvaluatedSurface s = surface_at(ray, met.hit, state, ctx, cone_width);
  return shade_surface(ray, s, cone_width, state, ctx);
}

[[gnu::always_inline]] inline EvaluatedSurface WhittedIntegrator::surface_at(const Ray& ray, const Hit& hit,
                                                                             const PathState& state, TraceContext& ctx,
                                                                             float& cone_width) const {
  const Scene& scene = ctx.scene;
  const SurfaceInteraction si = scene.surface(ray, hit);
  // One square root for the cone and the unit direction (glm::normalize's bits: d x (1 / |d|)),
  // none for a ray made unit.
  const float length = state.unit_direction ? 1.0f : glm::length(ray.direction);
  cone_width = state.cone_width + state.cone_spread * hit.t * length;
  const Material& m = scene.materials()[si.material];
  const Vec3 unit_direction = state.unit_direction ? ray.direction : ray.direction * (1.0f / length);
  EvaluatedSurface s =
      scene.is_uniform_phong(si.material)
          ? uniform_phong_surface(m, si, unit_direction)
          : evaluate_mapped_surface(m, si, unit_direction, scene.textures(), cone_width, ctx.settings.detail);
  s.prim = hit.prim;
  if (ctx.aovs) [[unlikely]]
    record_first_hit(ctx, s.diffuse, s.n, hit.t * length, s.emission);
  return s;
}

[[gnu::always_inline]] inline Vec3 WhittedIntegrator::shade_surface(const Ray& ray, const EvaluatedSurface& s,
                                                                    float cone_width, const PathState& state,
                                                                    TraceContext& ctx,
                                                                    const PointShadows* known) const {
  Vec3 radiance = s.emission + direct_lighting(s, state.path, max_component(state.weight) * state.share, ctx, known);
  const bool bounces = max_component(s.reflectivity) > 0.0f || s.transmissive();
  if (bounces && state.depth < ctx.settings.max_depth) radiance += secondary(s, state, cone_width, ctx);
  return absorbed(radiance, ray, state, ctx.scene);
}

Vec3 WhittedIntegrator::shade_no_surface(const Ray& ray, const SceneHit& met, const PathState& state,
                                         TraceContext& ctx) const {
  Vec3 radiance = ctx.scene.background.radiance(ray.direction);
  // An area light's face seen before any surface shows its emitted radiance, so mirrors show
  // the light's shape.
  if (met.light) {
    radiance = met.light->color;
    record_first_hit(ctx, Vec3(0.0f), met.light->normal(), ray.tmax * glm::length(ray.direction), radiance);
  } else {
    record_no_hit(ctx, radiance);
  }
  return absorbed(radiance, ray, state, ctx.scene);
}

Vec3 WhittedIntegrator::absorbed_in_medium(Vec3 radiance, const Ray& ray, const PathState& state,
                                           const Scene& scene) const {
  // Beer-Lambert along the segment just travelled (ray.tmax: to the surface or light it met),
  // inside the innermost medium. A ray that leaves through an open mesh without hitting anything
  // keeps tmax = infinity: it travelled forever and arrives dark.
  const Material& m = scene.materials()[state.media.innermost()];
  if (m.absorbing()) {
    const float distance = ray.tmax * glm::length(ray.direction);
    // Per channel, so that a channel that does not absorb is not multiplied by exp(-0 * inf).
    for (int c = 0; c < 3; ++c)
      if (m.absorption[c] > 0.0f) radiance[c] *= std::exp(-m.absorption[c] * distance);
  }
  return radiance;
}

WhittedIntegrator::PathState WhittedIntegrator::camera_state(int depth, const TraceContext& ctx) {
  PathState state;
  state.depth = depth;
  state.cone_spread = ctx.pixel_spread;
  state.cone_width = ctx.pixel_footprint;
  return state;
}

Vec3 WhittedIntegrator::radiance_from_hit(const Ray& camera_ray, const SceneHit& met, int depth,
                                          TraceContext& ctx) const {
  return shade(camera_ray, met, camera_state(depth, ctx), ctx);
}

void WhittedIntegrator::radiance_from_hits(const Ray* rays, const SceneHit* met, int count, TraceContext* const* ctx,
                                           Vec3* out) const {
  // Each surface is made in place where there is one. (A made array and copies into it cost
  // antialias.json 5%, measured.)
  StorageOnly<EvaluatedSurface, kPacketSize> surfaces;
  EvaluatedSurface* s = surfaces.at;
  float cone_width[kPacketSize];
  bool has[kPacketSize];
  for (int i = 0; i < count; ++i) {
    has[i] = met[i].surface;
    if (has[i])
      new (&s[i]) EvaluatedSurface(surface_at(rays[i], met[i].hit, camera_state(0, *ctx[i]), *ctx[i], cone_width[i]));
  }
  PointShadows known[kPacketSize];
  if (count > 0) find_point_shadows(s, has, count, ctx[0]->scene, ctx[0]->counters, known);
  for (int i = 0; i < count; ++i) {
    const PathState state = camera_state(0, *ctx[i]);
    out[i] = has[i] ? shade_surface(rays[i], s[i], cone_width[i], state, *ctx[i], &known[i])
                    : shade_no_surface(rays[i], met[i], state, *ctx[i]);
  }
}

// The caller's ray, not a copy: copied whole, it was loaded in wide loads from the narrow stores
// that had just made it, which no store forwards to (half of trace()'s samples in a profile of
// refraction.json; docs/benchmark.md, "Round two, a twenty-sixth session").
// trace(), traced_from() and spread() are inlined each into its caller, down to secondary(), and
// so are surface_at() and shade_surface() (shade(), above): a secondary ray then makes one call
// down the tree where it made six, each saving and restoring registers (refraction.json 4.2%
// fewer instructions, 0.967x then 0.985x the time; glossy.json 0.95x, reflection 0.97x).
[[gnu::always_inline]] inline Vec3 WhittedIntegrator::trace(Ray& ray, const PathState& state, TraceContext& ctx,
                                                            RayStart from) const {
  SceneHit met;
  ctx.scene.intersect(ray, met, from);
  return shade(ray, met, state, ctx);
}

Vec3 WhittedIntegrator::secondary(const EvaluatedSurface& s, const PathState& state, float cone_width,
                                  TraceContext& ctx) const {
  // The ray's unit direction as evaluate_surface made it, the same bits: normalised again here,
  // with surface_at's length, it took three square roots a hit (reflection.json 0.972x the time).
  const Vec3 d = -s.wo;
  Vec3 reflect_weight = s.reflectivity;
  Vec3 refract_weight(0.0f);
  Vec3 refracted(0.0f);
  // What the refracted ray travels through, made only where there is one; the path's state is
  // copied once a hit, into the children's.
  MediumCrossing crossing;
  if (s.transmissive()) {
    crossing = cross_medium(state.media, s.medium, s.entering, ctx.scene.materials());
    const float n1 = crossing.n_before, n2 = crossing.n_after;
    float fresnel = schlick_reflectance(glm::dot(s.wo, s.n), n1, n2);
    // Total internal reflection sends everything to the reflected ray. A shading normal can bend
    // the refracted ray back out of the surface; then the geometric normal decides.
    if (fresnel < 1.0f && (!refract(d, s.n, n1 / n2, refracted) || glm::dot(refracted, s.ng) >= 0.0f) &&
        !refract(d, s.ng, n1 / n2, refracted))
      fresnel = 1.0f;
    // A Phong material's transmission colours what the interface reflects too (its documented
    // rule); glTF's tints only what passes through (KHR_materials_transmission).
    reflect_weight += (s.pbr ? Vec3(s.transmission_factor) : s.transmission) * fresnel;
    refract_weight = s.transmission * (1.0f - fresnel);
    // Below a glossy split each ray stays one ray (spread()): at glass it follows the reflection
    // or the refraction, drawn by their weights, rather than both, so a rough glass ball costs
    // glossy_samples x depth rays, not glossy_samples x 2^depth. (The split's rays average the
    // choices; the expected colour is the same.)
    const float reflect_part = max_component(reflect_weight), refract_part = max_component(refract_weight);
    if (state.split && reflect_part > 0.0f && refract_part > 0.0f) {
      const float p_reflect = reflect_part / (reflect_part + refract_part);
      const float u = ctx.samples.get2(SamplePurpose::kGlossy, child_path(state.path, kFresnelChoice, 0), 0).x;
      if (u < p_reflect) {
        reflect_weight /= p_reflect;
        refract_weight = Vec3(0.0f);
      } else {
        refract_weight /= 1.0f - p_reflect;
        reflect_weight = Vec3(0.0f);
      }
    }
  }
  Vec3 sum(0.0f);
  PathState next = state;
  ++next.depth;
  next.unit_direction = true;
  next.cone_width = cone_width;
  if (max_component(state.weight * reflect_weight) >= kMinWeight) {
    next.weight = state.weight * reflect_weight;
    next.path = child_path(state.path, kReflected, 0);
    Vec3 mirror = reflect(d, s.n);
    if (glm::dot(mirror, s.ng) <= 0.0f) mirror = reflect(d, s.ng);  // never into the surface
    sum += reflect_weight * spread(s, mirror, s.glossy, RayKind::kReflection, max_component(reflect_weight), next, ctx);
  }
  if (max_component(state.weight * refract_weight) >= kMinWeight) {
    next.weight = state.weight * refract_weight;
    next.media = crossing.beyond;
    next.path = child_path(state.path, kRefracted, 0);
    sum += refract_weight *
           spread(s, refracted, s.refraction_glossy, RayKind::kRefraction, max_component(refract_weight), next, ctx);
  }
  return sum;
}

// The mirror (or refracted) ray, or the proposal's glossy rays around it: glossy_samples rays
// stratified over the blur square of `width` (glossy.h), random numbers keyed by this ray's path
// (core/sampling.h). Rays that fall on the wrong side of the surface (below it for a reflection,
// above it for a refraction) are discarded and the rest averaged; if all fall there, the central
// ray stands in. Only the first glossy hit of a path splits; glossy hits below it trace one
// jittered ray each, so a ray tree costs glossy_samples x depth rays rather than
// glossy_samples ^ depth; at glass below a split, one of the two branches is followed
// (secondary()). A refracted ray spreads for glTF's rough transmission; at glass the branches
// split in proportion to their weight (`branch_weight`), at least one ray each.
[[gnu::always_inline]] inline Vec3 WhittedIntegrator::spread(const EvaluatedSurface& s, Vec3 centre, float width,
                                                             RayKind kind, float branch_weight, const PathState& state,
                                                             TraceContext& ctx) const {
  if (!ctx.settings.glossy || width <= 0.0f || ctx.settings.glossy_samples < 1)
    return traced_from(s, centre, kind, state, ctx);
  const bool through = kind == RayKind::kRefraction;
  // At glass the two branches share the split by their weights (a 4 % Fresnel reflection takes
  // one ray of 8, the refraction 8): rays follow what they add, as scaled shadow samples do.
  int count = state.split ? 1 : ctx.settings.glossy_samples;
  if (count > 1 && s.transmissive()) count = secondary_shadow_samples(count, branch_weight);
  const StratifiedGrid grid(count);
  Vec3 u, v;
  hughes_moller_basis(centre, u, v);
  PathState below = state;
  below.split = true;
  below.share = state.share / static_cast<float>(count);
  const uint32_t branch = through ? kGlossyRefraction : kGlossyRay;
  Vec3 sum(0.0f);
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    // Reflection keeps the keys it always had; refraction's are another path's.
    const uint64_t key = through ? child_path(state.path, kGlossyRefraction, 0) : state.path;
    const Vec2 jitter = ctx.samples.get2(SamplePurpose::kGlossy, key, static_cast<uint64_t>(i));
    const Vec3 direction = glossy_direction(centre, u, v, width, grid.point(i, jitter));
    if ((glm::dot(direction, s.ng) <= 0.0f) != through) continue;
    below.path = child_path(state.path, branch, static_cast<uint32_t>(i));
    sum += traced_from(s, direction, through ? RayKind::kRefraction : RayKind::kGlossy, below, ctx);
    ++kept;
  }
  if (kept == 0) return traced_from(s, centre, kind, state, ctx);
  return sum / static_cast<float>(kept);
}

[[gnu::always_inline]] inline Vec3 WhittedIntegrator::traced_from(const EvaluatedSurface& s, Vec3 direction,
                                                                  RayKind kind, const PathState& state,
                                                                  TraceContext& ctx) const {
  Ray ray;
  ray.origin = offset_ray_origin(s.position, s.position_error, s.ng, direction);
  ray.direction = direction;
  ++ctx.counters[kind];
  // Into the surface's own primitive (a refraction entering it, a reflection on its inside): if
  // that is a closed shape, what the ray can meet is known without a walk. Out of it: a shape is
  // not tested. Told by the ray's kind, not its direction (every ray here leaves on the side its
  // kind says: secondary() and spread() see to it): a dot product here spilled the direction and
  // read it back in a load no store forwards to (reflection.json 1.02x the time).
  const bool inwards = (kind == RayKind::kRefraction) == s.entering;
  return trace(ray, state, ctx, RayStart{s.prim, inwards});
}

}  // namespace rt
