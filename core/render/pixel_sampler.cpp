#include "core/render/pixel_sampler.h"

#include "core/render/adaptive_sampler.h"

namespace rt {

Vec3 trace_camera_sample(float px, float py, const SampleStream& samples, PixelContext& ctx, float spacing) {
  const RenderSettings& s = ctx.settings;
  const Camera& camera = ctx.view();
  if (!camera.sees(px, py, s.width, s.height)) return Vec3(0.0f);  // outside a fisheye's circle
  TraceContext trace{ctx.scene,
                     s,
                     ctx.counters,
                     samples,
                     spacing * camera.pixel_spread(s.width, s.height),
                     spacing * camera.pixel_footprint(s.width, s.height)};
  ++ctx.counters[RayKind::kCamera];
  // The lens sample is keyed like every other number: a pinhole camera ignores it.
  const Vec2 lens = trace.samples.get2(SamplePurpose::kLens, 0, 0);
  return ctx.integrator.radiance(camera.generate_ray(px, py, s.width, s.height, lens), 0, trace);
}

namespace {

// The keyed numbers of camera sample `sample` of pixel (x, y): the same whichever thread asks.
SampleStream pixel_stream(int x, int y, uint32_t sample, const PixelContext& ctx) {
  const RenderSettings& s = ctx.settings;
  const uint64_t pixel_index = static_cast<uint64_t>(y) * static_cast<uint64_t>(s.width) + static_cast<uint64_t>(x);
  return SampleStream(s.seed, ctx.frame, ctx.point_key(pixel_index), sample);
}

// A sampler whose pixels are independent of each other: the tile is its pixels in turn.
class PerPixelSampler : public PixelSampler {
 public:
  bool render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) override {
    return render_pixels(tile, ctx, out, [&](int x, int y) { return pixel(x, y, ctx); });
  }

 private:
  virtual FilmPixel pixel(int x, int y, PixelContext& ctx) const = 0;
};

// One ray through the pixel centre: the proposal's baseline, aliased edges and all.
class CentreSampler final : public PerPixelSampler {
  FilmPixel pixel(int x, int y, PixelContext& ctx) const override {
    const Vec3 c = trace_camera_sample(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f,
                                       pixel_stream(x, y, 0, ctx), ctx);
    return FilmPixel{c, 1, 0};
  }
};

// n x n rays on a regular sub-pixel grid, averaged with equal weights: at the cell centres, or
// with `jitter` at a keyed random point of each cell (stratified sampling: edges turn from stair
// steps into fine noise).
class UniformSampler final : public PerPixelSampler {
 public:
  UniformSampler(int n, bool jitter) : n_(n), jitter_(jitter) {}

 private:
  FilmPixel pixel(int x, int y, PixelContext& ctx) const override {
    Vec3 sum(0.0f);
    const float step = 1.0f / static_cast<float>(n_);
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i < n_; ++i) {
        const SampleStream samples = pixel_stream(x, y, static_cast<uint32_t>(j * n_ + i), ctx);
        const Vec2 offset = jitter_ ? samples.get2(SamplePurpose::kPixel, 0, 0) : Vec2(0.5f);
        sum += trace_camera_sample(static_cast<float>(x) + (static_cast<float>(i) + offset.x) * step,
                                   static_cast<float>(y) + (static_cast<float>(j) + offset.y) * step, samples, ctx,
                                   step);
      }
    return FilmPixel{sum * (step * step), static_cast<uint16_t>(n_ * n_), 0};
  }

  int n_;
  bool jitter_;
};

std::unique_ptr<PixelSampler> make_centre(const AntialiasSettings&, const TileGrid&) {
  return std::make_unique<CentreSampler>();
}
std::unique_ptr<PixelSampler> make_uniform(const AntialiasSettings& aa, const TileGrid& grid) {
  if (aa.samples <= 1 && !aa.jitter) return make_centre(aa, grid);  // the same single ray
  return std::make_unique<UniformSampler>(aa.samples, aa.jitter);
}
std::unique_ptr<PixelSampler> make_adaptive(const AntialiasSettings& aa, const TileGrid& grid) {
  return std::make_unique<AdaptiveSampler>(aa, grid);
}

struct Entry {
  const char* name;
  std::unique_ptr<PixelSampler> (*make)(const AntialiasSettings&, const TileGrid&);
};

// The name table (render.antialias.mode). Adding a sampler = one file and one line here.
constexpr Entry kSamplers[] = {{"none", &make_centre}, {"uniform", &make_uniform}, {"adaptive", &make_adaptive}};

}  // namespace

std::unique_ptr<PixelSampler> make_pixel_sampler(const RenderSettings& settings, const TileGrid& grid) {
  for (const Entry& e : kSamplers)
    if (settings.antialias.mode == e.name) return e.make(settings.antialias, grid);
  return nullptr;
}

std::vector<std::string> pixel_sampler_names() {
  std::vector<std::string> names;
  for (const Entry& e : kSamplers) names.emplace_back(e.name);
  return names;
}

}  // namespace rt
