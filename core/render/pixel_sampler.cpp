#include "core/render/pixel_sampler.h"

namespace rt {
namespace {

// The keyed numbers of camera sample `sample` of pixel (x, y): the same whichever thread asks.
SampleStream sample_stream(int x, int y, uint32_t sample, const PixelContext& ctx) {
  const RenderSettings& s = ctx.settings;
  const uint64_t pixel_index = static_cast<uint64_t>(y) * static_cast<uint64_t>(s.width) + static_cast<uint64_t>(x);
  return SampleStream(s.seed, ctx.frame, pixel_index, sample);
}

// Radiance of one camera sample at continuous pixel position (px, py), with its keyed numbers.
Vec3 trace_sample(float px, float py, const SampleStream& samples, PixelContext& ctx) {
  const RenderSettings& s = ctx.settings;
  TraceContext trace{ctx.scene, s, ctx.counters, samples};
  ++ctx.counters[RayKind::kCamera];
  // The lens sample is keyed like every other number: a pinhole camera ignores it.
  const Vec2 lens = trace.samples.get2(SamplePurpose::kLens, 0, 0);
  return ctx.integrator.radiance(ctx.scene.camera.generate_ray(px, py, s.width, s.height, lens), 0, trace);
}

// One ray through the pixel centre: the proposal's baseline, aliased edges and all.
class CentreSampler final : public PixelSampler {
 public:
  Vec3 pixel(int x, int y, PixelContext& ctx) const override {
    return trace_sample(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, sample_stream(x, y, 0, ctx), ctx);
  }
};

// n x n rays on a regular sub-pixel grid, averaged with equal weights: at the cell centres, or
// with `jitter` at a keyed random point of each cell (stratified sampling: edges turn from stair
// steps into fine noise).
class UniformSampler final : public PixelSampler {
 public:
  UniformSampler(int n, bool jitter) : n_(n), jitter_(jitter) {}
  Vec3 pixel(int x, int y, PixelContext& ctx) const override {
    Vec3 sum(0.0f);
    const float step = 1.0f / static_cast<float>(n_);
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i < n_; ++i) {
        const SampleStream samples = sample_stream(x, y, static_cast<uint32_t>(j * n_ + i), ctx);
        const Vec2 offset = jitter_ ? samples.get2(SamplePurpose::kPixel, 0, 0) : Vec2(0.5f);
        sum += trace_sample(static_cast<float>(x) + (static_cast<float>(i) + offset.x) * step,
                            static_cast<float>(y) + (static_cast<float>(j) + offset.y) * step, samples, ctx);
      }
    return sum * (step * step);
  }

 private:
  int n_;
  bool jitter_;
};

}  // namespace

std::unique_ptr<PixelSampler> make_pixel_sampler(const RenderSettings& settings) {
  if (settings.sampler == PixelSamplerKind::kUniform && settings.samples_per_axis > 1)
    return std::make_unique<UniformSampler>(settings.samples_per_axis, settings.jitter);
  return std::make_unique<CentreSampler>();
}

}  // namespace rt
