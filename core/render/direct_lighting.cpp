#include "core/render/direct_lighting.h"

#include <algorithm>
#include <new>
#include <optional>

#include "core/lights/rect_light_batch.h"
#include "core/lights/stratified_grid_batch.h"
#include "core/render/scene_lights.h"
#include "core/render/shadow_transmittance.h"
#include "core/storage_only.h"
#include "materials/phong.h"
#include "materials/phong_batch.h"

namespace rt {

namespace {

// Fewer shadow rays than this to one light are traced one by one: a packet's walk tests every
// child box for all its lanes, which pays only when enough of them are in use (measured:
// docs/benchmark.md, "Shadow-ray packets").
constexpr int kMinShadowPacket = 4;
// Fewer samples of an area light than this trace their shadow rays without first asking which
// leaves of the BVH they can reach (ShadowRays::leaves_towards): the query costs a few rays.
constexpr int kMinShadowVolume = 4;

// A light sample whose share of the sample's value is below this, unshadowed, adds nothing and
// gets no shadow ray, at a point without kd (where Phong's factor is known before the ray): the
// skirt of a narrow highlight, Hall and Greenberg's adaptive depth for light as kMinWeight is
// for rays. 2^-14 is a fifth of the darkest 8-bit step (sRGB 1/255 is 0.0003 linear). Glass of
// shininess 300 under a light of 1 traces shadow rays within 14 degrees of its mirror direction,
// not 45 (where the float power becomes 0).
constexpr float kFaintLight = 0x1p-14f;

// `share`: the sample's part of the hit's direct light, times the hit's weight in its sample.
bool faint(Vec3 reflectance, Vec3 radiance, float share) {
  return max_component(reflectance * radiance) * share < kFaintLight;
}

// The shadow rays from one surface point. Where they start: shadow_ray_origin depends on the
// direction only by the side of the geometric normal it leaves on, so the two origins are made
// once per point, not per sample (4% of a soft-shadow render went there; the same floats).
class ShadowRays {
 public:
  explicit ShadowRays(const EvaluatedSurface& s)
      : s_(&s),
        lifted_(s.shadow_lift != Vec3(0.0f)),
        front_(shadow_ray_origin(s, s.ng)),
        back_(lifted_ ? shadow_ray_origin(s, -s.ng) : front_) {}

  // The shadow ray towards a light sample (its direction, distance and radiance), or false when
  // the sample cannot light the point.
  bool make(Vec3 direction, float distance, Vec3 radiance, Ray& shadow) const {
    const EvaluatedSurface& s = *s_;
    // A light behind the geometric surface cannot reach it, whatever the shading normal says;
    // except on a smooth mesh (a lift), whose facets only stand in for the curved surface:
    // there the shadow ray from the lifted point decides, as in Cycles, so that the terminator
    // follows the normals rather than the facets' edges.
    if (glm::dot(s.n, direction) <= 0.0f) return false;
    if (glm::dot(s.ng, direction) <= 0.0f && !lifted_) return false;
    if (max_component(radiance) <= 0.0f) return false;  // the dark back of an area light
    ray(direction, distance, glm::dot(direction, s.ng) < 0.0f, shadow);
    return true;
  }

  // The shadow ray towards a sample that passed make's tests (as sample_sides, core/lights/
  // rect_light_batch.h, finds them), `behind` where it leaves the geometric surface's back.
  // Written a number at a time: a Ray built apart and copied whole was loaded as one vector from
  // those narrow stores, which no store forwards to (soft_shadows.json 1.17x the time).
  void ray(Vec3 direction, float distance, bool behind, Ray& shadow) const {
    // From the lifted point on a smooth mesh (Hanika), along the same direction: the light is
    // far beside a lift of a fraction of a facet.
    shadow.origin = behind ? back_ : front_;
    shadow.direction = direction;
    shadow.tmin = 0.0f;
    // Stop just short of the light so a surface the light sits on does not shadow it.
    shadow.tmax = distance * (1.0f - kShadowEpsilon);
  }

  // The leaves of `bvh` that the shadow rays to `light` can meet: those whose boxes meet the
  // pyramid of the rays' origin and the light (core/accel/shadow_volume.h). False when unknown: a
  // lifted point's rays start from two origins, or more leaves than a set holds.
  bool leaves_towards(const RectLight& light, const Bvh& bvh, BvhLeafSet& out) const {
    return !lifted_ && bvh.leaves_meeting(ShadowVolume(front_, light.corner, light.edge1, light.edge2), out);
  }

 private:
  const EvaluatedSurface* s_;
  bool lifted_;
  Vec3 front_, back_;
};

// The emissive surfaces as Whitted sees them, through the light interface
// (core/render/scene_lights.h): `count` points drawn from them by area x emission, each lighting
// by the point-light rule as the path tracer's sample would, L / (pi x density): a floor under a
// glowing ball is as bright as path traced (tests/render/test_light_units.cpp).
template <class ShadowRay, class Lit>
Vec3 emitted_light(const EvaluatedSurface& s, uint64_t path, int count, const ShadowRay& shadow_ray, const Lit& lit,
                   TraceContext& ctx) {
  const Scene& scene = ctx.scene;
  Vec3 sum(0.0f);
  for (int i = 0; i < count; ++i) {
    LightSample ls = sample_area_li(scene, scene.lights.size(), s.position, ctx.samples, path, ctx.settings.detail,
                                    static_cast<uint32_t>(i));
    if (!(ls.pdf > 0.0f)) continue;
    ls.radiance /= kPi * ls.pdf;
    Ray shadow;
    if (!shadow_ray(ls.direction, ls.distance, ls.radiance, shadow)) continue;
    const Vec3 visible = shadow_transmittance(scene, shadow);
    if (max_component(visible) > 0.0f) sum += lit(ls.direction, ls.radiance, visible);
  }
  return sum / static_cast<float>(count);
}

// A rect light's samples at `s`, summed (direct_lighting divides by `count`). Out of line: its
// batches' arrays made direct_lighting's frame 1.3 KB, set up at every hit that a point light
// lights too.
[[gnu::noinline]] Vec3 rect_light_sum(const EvaluatedSurface& s, size_t l, const RectLight* rect, int samples,
                                      int count, float weight, uint64_t path, std::optional<ShadowRays>& rays_from,
                                      TraceContext& ctx) {
  const Scene& scene = ctx.scene;
  Vec3 light_sum(0.0f);
  // Whitted's rule for a rect light (core/lights/rect_light.h): each sample lights as a point
  // light of its colour would, times the light's attenuation and its cosine towards the
  // point. The samples are worked out a batch at a time in vector registers
  // (core/lights/rect_light_batch.h), their numbers sixteen at a time (SampleStream::get2_batch). With
  // opaque blockers only, enough shadow rays go in packets (Bvh::occluded_packet), each
  // sample that reaches the light then adding its share in sample order: the same sum. (With
  // glass, asking the packet first and walking the rays it finds crossing something for
  // their transmittance gave panorama 0.90x but csg 1.18x, whose CSG spans were then found
  // twice: measured, and left out.)
  // One sample sits at the light's centre when the scene asks for one (a hard shadow, as
  // before); one left by scaling is jittered over the light, so reflections keep soft shadows.
  const bool centred = samples == 1 && ctx.settings.shadow_samples == 1;
  const RectFrame frame = scene.rect_frame(l);  // the scene's, not per sample
  const StratifiedGrid grid(count);
  // Which leaves of the BVH the samples' shadow rays can meet, asked once for all of them: on
  // a floor away from everything, none (the same answers). Asked only where the rays are
  // walked one by one for their transmittance (a scene with glass): the query costs about
  // what the packets' walk of a point's 16 rays saved, soft_shadows.json 1.13x (measured in
  // docs/benchmark.md, "Round two, a ninth session").
  // Not asked at a point without kd, which traces few rays, if any (below).
  BvhLeafSet among;
  const BvhLeafSet* reach = nullptr;
  if (!scene.all_opaque && count >= kMinShadowVolume && s.diffuse != Vec3(0.0f)) {
    if (!rays_from) rays_from.emplace(s);
    if (rays_from->leaves_towards(*rect, scene.bvh, among)) reach = &among;
  }
  const bool packets = scene.all_opaque && count >= kMinShadowPacket;
  // The numbers of samples [base - k, base - k + kMaxSobolPairs), k = base % kMaxSobolPairs.
  static_assert(kMaxSobolPairs % kPacketSize == 0);
  float jx[kMaxSobolPairs] = {}, jy[kMaxSobolPairs] = {};         // all read, eight at a time
  const float sample_share = weight / static_cast<float>(count);  // one sample's part, for faint()
  for (int base = 0; base < count; base += kPacketSize) {
    const int batch = std::min(kPacketSize, count - base);
    float u[2][kPacketSize] = {};
    if (count == 1 && centred) {
      u[0][0] = u[1][0] = 0.5f;
    } else {
      const int k = base % kMaxSobolPairs;
      if (k == 0)
        ctx.samples.get2_batch(SamplePurpose::kLight, path, light_dimension(l, static_cast<uint32_t>(base)),
                               std::min(kMaxSobolPairs, count - base), jx, jy);
      stratified_points_batch(grid, base, jx + k, jy + k, u);
    }
    RectLightBatch drawn;
    rect_light_batch(*rect, frame, s.position, u, drawn);
    // lit(...)'s Phong factor, for the samples that reach the light (a shadowed one's powers
    // are not worked out).
    PhongBatch reflectance;
    const auto reflectance_of = [&](unsigned lanes) {
      phong_batch(s.diffuse, s.specular, s.shininess, s.n, s.wo, drawn.dx, drawn.dy, drawn.dz, lanes, reflectance);
    };
    // Without kd, every sample's factor first, as for a point light above: a faint one gets no ray.
    const bool specular_only = s.diffuse == Vec3(0.0f);
    if (specular_only) reflectance_of((1u << batch) - 1u);
    // ShadowRays::make's tests for all the batch's samples at once.
    const SampleSides sides = sample_sides(drawn, rect->color, s.n, s.ng, s.shadow_lift != Vec3(0.0f));
    Ray shadows[kPacketSize];
    int ray_of[kPacketSize];  // which shadow ray a sample has; -1: none
    int rays = 0;
    for (int j = 0; j < batch; ++j) {
      ray_of[j] = -1;
      if (!(sides.light >> j & 1u) ||
          (specular_only && faint(reflectance[j], rect->color * drawn.scale[j], sample_share)))
        continue;
      if (!rays_from) rays_from.emplace(s);
      rays_from->ray(drawn.direction(j), drawn.distance[j], sides.behind >> j & 1u, shadows[rays]);
      ray_of[j] = rays++;
    }
    ctx.counters[RayKind::kShadow] += static_cast<uint64_t>(rays);
    unsigned reaching = 0;  // the samples that reach the light
    Vec3 visible[kPacketSize];
    if (packets) {
      const unsigned blocked = scene.occluded_packet(shadows, rays);
      for (int j = 0; j < batch; ++j)
        if (ray_of[j] >= 0 && !(blocked >> ray_of[j] & 1u)) reaching |= 1u << j;
      if (!specular_only) reflectance_of(reaching);
      add_lit(reflectance, rect->color, drawn.scale, reaching, light_sum);
      continue;
    }
    for (int j = 0; j < batch; ++j) {
      if (ray_of[j] < 0) continue;
      visible[j] = shadow_transmittance(scene, shadows[ray_of[j]], reach);
      if (max_component(visible[j]) > 0.0f) reaching |= 1u << j;
    }
    if (!specular_only) reflectance_of(reaching);
    for (int j = 0; j < batch; ++j)
      if (reaching >> j & 1u) light_sum += visible[j] * (rect->color * drawn.scale[j]) * reflectance[j];
  }
  return light_sum;
}

}  // namespace

Vec3 shadow_ray_origin(const EvaluatedSurface& s, Vec3 direction) {
  if (s.shadow_lift == Vec3(0.0f)) return offset_ray_origin(s.position, s.position_error, s.ng, direction);
  // The lifted point's bound: the sum's own rounding on top of the point's.
  const Vec3 lifted_error = s.position_error + float_gamma(1) * abs3(s.position + s.shadow_lift);
  return offset_ray_origin(s.position + s.shadow_lift, lifted_error, s.ng, direction);
}

Vec3 direct_lighting(const EvaluatedSurface& s, uint64_t path, float weight, TraceContext& ctx,
                     const PointShadows* known) {
  const Scene& scene = ctx.scene;
  Vec3 sum = scene.ambient * s.diffuse;
  // An area light's or the emitters' samples: worked out only for them (its ceil's conversions were
  // 1% of refraction.json, which a point light lights).
  const auto area_samples = [&] {
    return ctx.settings.scale_secondary_shadows ? secondary_shadow_samples(ctx.settings.shadow_samples, weight)
                                                : ctx.settings.shadow_samples;
  };
  std::optional<ShadowRays> rays_from;  // made when first asked: none where `known` answers all
  const auto shadow_ray = [&](Vec3 direction, float distance, Vec3 radiance, Ray& shadow) {
    if (!rays_from) rays_from.emplace(s);
    if (!rays_from->make(direction, distance, radiance, shadow)) return false;
    ++ctx.counters[RayKind::kShadow];
    return true;
  };
  const auto lit = [&](Vec3 direction, Vec3 radiance, Vec3 visible) {
    return visible * radiance * phong_reflectance(s.diffuse, s.specular, s.shininess, s.n, direction, s.wo);
  };
  for (size_t l = 0; l < scene.lights.size(); ++l) {
    const Light& light = scene.lights[l];
    // A point light is one sample; an area light shadow_samples points stratified over it, one
    // jittered sample per cell, each used for the shadow ray and for Phong, averaged.
    const RectLight* rect = std::get_if<RectLight>(&light);
    const int samples = rect ? area_samples() : 1;
    const int count = light_sample_count(light, samples);
    Vec3 light_sum(0.0f);
    if (!rect && known && l < PointShadows::kMaxLights && (known->known >> l & 1u)) {  // traced before
      if (known->lit >> l & 1u) light_sum += lit(known->direction[l], known->radiance[l], Vec3(1.0f));
    } else if (!rect) {  // a point, spot or directional light: one sample, one shadow ray
      const LightSample ls = sample_li(light, s.position, Vec2(0.5f));
      // Without kd (glass, a mirror), Phong's factor first: away from the narrow highlight the
      // light adds (next to) nothing, and no shadow ray is traced to find that out (kFaintLight).
      // (With kd it is never 0 where the light is in front, and a shadowed point's power is not
      // worked out.)
      const bool specular_only = s.diffuse == Vec3(0.0f);
      const Vec3 reflectance =
          specular_only ? phong_reflectance(s.diffuse, s.specular, s.shininess, s.n, ls.direction, s.wo) : Vec3(1.0f);
      Ray shadow;
      if (!(specular_only && faint(reflectance, ls.radiance, weight)) &&
          shadow_ray(ls.direction, ls.distance, ls.radiance, shadow)) {
        const Vec3 visible = shadow_transmittance(scene, shadow);
        if (max_component(visible) > 0.0f)
          light_sum += specular_only ? visible * ls.radiance * reflectance : lit(ls.direction, ls.radiance, visible);
      }
    } else {
      light_sum = rect_light_sum(s, l, rect, samples, count, weight, path, rays_from, ctx);
    }
    sum += count == 1 ? light_sum : light_sum / static_cast<float>(count);  // x / 1 is x: not divided
  }
  if (!scene.emitters.empty()) sum += emitted_light(s, path, area_samples(), shadow_ray, lit, ctx);
  return sum;
}

void find_point_shadows(const EvaluatedSurface* s, const bool* has, int count, const Scene& scene,
                        RayCounters& counters, PointShadows* out) {
  for (int i = 0; i < count; ++i) out[i].known = out[i].lit = 0;
  // With glass, a ray the packet finds blocked may only be filtered: left to shadow_transmittance,
  // which counts it then. One that meets nothing is lit, glass or not.
  const bool opaque = scene.all_opaque;
  // Each made where there is a point: optionals' flags were set by zeroing the whole array, a
  // 384-byte `rep stos` per packet (8% of this function's samples).
  StorageOnly<ShadowRays, kPacketSize> from;
  for (int i = 0; i < count; ++i)
    if (has[i]) new (&from.at[i]) ShadowRays(s[i]);
  const size_t lights = std::min(scene.lights.size(), PointShadows::kMaxLights);
  for (size_t l = 0; l < lights; ++l) {
    const Light& light = scene.lights[l];
    if (std::holds_alternative<RectLight>(light)) continue;
    const uint32_t bit = 1u << l;
    Ray rays[kPacketSize];
    int owner[kPacketSize];  // which point ray k leaves from
    int made = 0;
    std::visit(  // once per light, not per point
        [&](const auto& typed) {
          for (int i = 0; i < count; ++i) {
            if (!has[i]) continue;
            out[i].known |= bit;  // a point without a ray is known too: the light does not reach it
            const LightSample ls = sample_li(typed, s[i].position, Vec2(0.5f));
            // As direct_lighting: no ray where a point without kd reflects little of the light
            // (a camera ray's hit: its weight is 1).
            const EvaluatedSurface& p = s[i];
            if (p.diffuse == Vec3(0.0f) &&
                faint(phong_reflectance(p.diffuse, p.specular, p.shininess, p.n, ls.direction, p.wo), ls.radiance,
                      1.0f))
              continue;
            if (!from.at[i].make(ls.direction, ls.distance, ls.radiance, rays[made])) continue;
            out[i].direction[l] = ls.direction;
            out[i].radiance[l] = ls.radiance;
            owner[made++] = i;
          }
        },
        light);
    unsigned blocked = 0;
    if (made >= kMinShadowPacket) {
      blocked = scene.occluded_packet(rays, made);
    } else if (opaque) {
      for (int k = 0; k < made; ++k) blocked |= scene.occluded(rays[k]) ? 1u << k : 0u;
    } else {
      blocked = (1u << made) - 1u;  // too few for a packet: each traced through the glass later
    }
    int left = 0;
    for (int k = 0; k < made; ++k) {
      if (!(blocked >> k & 1u)) {
        out[owner[k]].lit |= bit;
      } else if (!opaque) {
        out[owner[k]].known &= ~bit;
        ++left;
      }
    }
    counters[RayKind::kShadow] += static_cast<uint64_t>(made - left);
  }
}

}  // namespace rt
