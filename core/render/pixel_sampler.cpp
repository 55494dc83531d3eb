#include "core/render/pixel_sampler.h"

#include <algorithm>
#include <new>

#include "core/render/adaptive_sampler.h"
#include "core/render/camera_ray_batch.h"
#include "core/render/path_sampler.h"
#include "core/storage_only.h"

namespace rt {

void CameraBatch::trace(PixelContext& ctx) {
  const RenderSettings& s = ctx.settings;
  const Camera& camera = ctx.view();
  StorageOnly<Ray, kPacketSize> made;  // each ray written whole where there is one
  Ray* rays = made.at;
  int ray_of[kPacketSize];  // which ray a sample has; -1: none (outside a fisheye's circle)
  int rays_made = 0;
  if (batches_camera_rays(camera)) {  // every sample sees, none reads a lens sample
    float px[kPacketSize], py[kPacketSize];
    for (int i = 0; i < count; ++i) {
      px[i] = sample[i].px;
      py[i] = sample[i].py;
      ray_of[i] = i;
    }
    static_assert(kPacketSize == kCameraRayBatch);
    perspective_ray_batch(camera, px, py, count, s.width, s.height, rays);
    rays_made = count;
  }
  for (int i = rays_made; i < count; ++i) {
    const CameraSample& c = sample[i];
    if (!camera.sees(c.px, c.py, s.width, s.height)) {
      ray_of[i] = -1;
      continue;
    }
    // The lens sample is keyed like every other number; a pinhole camera has no use for it.
    const Vec2 lens = camera.has_lens() ? c.samples.get2(SamplePurpose::kLens, 0, 0) : Vec2(0.5f);
    rays[rays_made] = camera.generate_ray(c.px, c.py, s.width, s.height, lens);
    ray_of[i] = rays_made++;
  }
  StorageOnly<SceneHit, kPacketSize> hits;  // intersect_packet writes each of the first rays_made
  SceneHit* met = hits.at;
  ctx.scene.intersect_packet(rays, met, rays_made);
  ctx.counters[RayKind::kCamera] += static_cast<uint64_t>(rays_made);
  // Each ray's context, in ray order, shaded together (Integrator::radiance_from_hits), made in
  // place where there is a ray (no flags to set and test, nothing to destroy).
  StorageOnly<TraceContext, kPacketSize> traces;
  TraceContext* trace_of[kPacketSize];
  const float spread = camera.pixel_spread(s.width, s.height), footprint = camera.pixel_footprint(s.width, s.height);
  for (int i = 0; i < count; ++i) {
    if (ctx.aovs) aovs[i] = Aovs{};
    if (ray_of[i] < 0) continue;
    const CameraSample& c = sample[i];
    trace_of[ray_of[i]] = new (&traces.at[ray_of[i]]) TraceContext{ctx.scene,
                                                                   s,
                                                                   ctx.counters,
                                                                   c.samples,
                                                                   c.spacing * spread,
                                                                   c.spacing * footprint,
                                                                   ctx.aovs ? &aovs[i] : nullptr};
  }
  Vec3 found[kPacketSize];
  ctx.integrator.radiance_from_hits(rays, met, rays_made, trace_of, found);
  for (int i = 0; i < count; ++i) radiance[i] = ray_of[i] < 0 ? Vec3(0.0f) : found[ray_of[i]];
}

namespace {

// n x n rays on a regular sub-pixel grid, averaged with equal weights: at the cell centres, or
// with `jitter` at a keyed random point of each cell (stratified sampling: edges turn from stair
// steps into fine noise). n = 1 without jitter: one ray through the pixel centre, the proposal's
// baseline, aliased edges and all. A tile row's samples are traced in packets of neighbours, and
// each pixel sums its own in sample order, as one at a time would.
class UniformSampler final : public PixelSampler {
 public:
  UniformSampler(int n, bool jitter) : n_(n), jitter_(jitter) {}

  bool render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) override {
    const float step = 1.0f / static_cast<float>(n_);
    // The sums of the pixels with samples in flight, by x modulo kOpen: at most a packet's worth
    // and one more, as every packet is traced once full.
    constexpr int kOpen = 2 * kPacketSize;
    Vec3 sums[kOpen];
    std::fill(sums, sums + kOpen, Vec3(0.0f));
    Aovs layers[kOpen];  // each sample adds its share
    const float share = step * step;
    CameraBatch batch;
    for (int y = tile.y0; y < tile.y1; ++y) {
      int written = tile.x0;  // the pixels left of this one are in `out`
      // Traces what is queued, then writes out the pixels left of x: all their samples are in.
      const auto drain = [&](int x) {
        batch.trace(ctx);
        for (int k = 0; k < batch.count; ++k) {
          sums[batch.tag[k] % kOpen] += batch.radiance[k];
          if (ctx.aovs) layers[batch.tag[k] % kOpen].add(batch.aovs[k], share);
        }
        batch.clear();
        for (; written < x; ++written) {
          Vec3& sum = sums[written % kOpen];
          out.at(written, y) = FilmPixel{sum * share, static_cast<uint16_t>(n_ * n_), 0, layers[written % kOpen]};
          sum = Vec3(0.0f);
          layers[written % kOpen] = Aovs{};
        }
      };
      for (int x = tile.x0; x < tile.x1; ++x) {
        if (ctx.cancelled()) return false;
        const SampleStream::PointKey pixel = batch.key(ctx, ctx.pixel_point(x, y));
        for (int j = 0; j < n_; ++j)
          for (int i = 0; i < n_; ++i) {
            CameraSample& c = batch.add(ctx, pixel, static_cast<uint32_t>(j * n_ + i), static_cast<uint32_t>(x));
            const Vec2 offset = jitter_ ? c.samples.get2(SamplePurpose::kPixel, 0, 0) : Vec2(0.5f);
            c.px = static_cast<float>(x) + (static_cast<float>(i) + offset.x) * step;
            c.py = static_cast<float>(y) + (static_cast<float>(j) + offset.y) * step;
            c.spacing = step;
            if (batch.full()) drain(x);
          }
      }
      drain(tile.x1);
      ctx.row_done(tile.width());
    }
    return true;
  }

 private:
  int n_;
  bool jitter_;
};

std::unique_ptr<PixelSampler> make_centre(const AntialiasSettings&, const TileGrid&) {
  return std::make_unique<UniformSampler>(1, false);
}
std::unique_ptr<PixelSampler> make_uniform(const AntialiasSettings& aa, const TileGrid& grid) {
  if (aa.samples <= 1 && !aa.jitter) return make_centre(aa, grid);  // the same single ray
  return std::make_unique<UniformSampler>(aa.samples, aa.jitter);
}
std::unique_ptr<PixelSampler> make_adaptive(const AntialiasSettings& aa, const TileGrid& grid) {
  return std::make_unique<AdaptiveSampler>(aa, grid);
}

// The name table (render.antialias.mode). Adding a sampler = one file and one line here.
constexpr NameEntry<PixelSamplerKind> kSamplerEntries[] = {
    {"none", {&make_centre}, "one ray through each pixel's centre"},
    {"uniform", {&make_uniform}, "N x N rays per pixel"},
    {"adaptive", {&make_adaptive}, "cells split where their samples differ (default)"}};
constexpr NameTable<PixelSamplerKind> kSamplers{kSamplerEntries};

}  // namespace

const NameTable<PixelSamplerKind>& pixel_samplers() { return kSamplers; }

std::unique_ptr<PixelSampler> make_pixel_sampler(const RenderSettings& settings, const TileGrid& grid) {
  if (integrator_samples_pixels(settings.integrator)) return std::make_unique<PathSampler>(settings.path);
  const NameEntry<PixelSamplerKind>* e = kSamplers.find(settings.antialias.mode);
  return e ? e->value.make(settings.antialias, grid) : nullptr;
}

}  // namespace rt
