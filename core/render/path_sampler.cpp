#include "core/render/path_sampler.h"

#include <cmath>

namespace rt {

float mean_variance(double sum, double sum_squares, int n) {
  if (n < 2) return 0.0f;
  const double mean = sum / n;
  return static_cast<float>(std::max(0.0, (sum_squares - sum * mean) / (n - 1)) / n);
}

float pixel_relative_error(double sum, double sum_squares, int n) {
  if (n < 2) return kInfinity;
  const double mean = sum / n;
  const double variance = std::max(0.0, (sum_squares - sum * mean) / (n - 1));
  return static_cast<float>(std::sqrt(variance / n) / std::max(mean, static_cast<double>(PathSampler::kNoiseFloor)));
}

bool PathSampler::render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) {
  const RenderSettings& s = ctx.settings;
  const int spp = std::max(1, settings_.samples_per_pixel);
  CameraBatch batch;
  for (int y = tile.y0; y < tile.y1; ++y) {
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (ctx.cancelled()) return false;
      const uint64_t pixel = static_cast<uint64_t>(y) * static_cast<uint64_t>(s.width) + static_cast<uint64_t>(x);
      Vec3 sum(0.0f);
      Aovs layers;  // summed, then scaled by 1 / n
      double luminance = 0.0, luminance_squares = 0.0;
      int n = 0;
      while (n < spp) {
        const int count = std::min(kPacketSize, spp - n);
        for (int i = 0; i < count; ++i) {
          const SampleStream samples(s.seed, ctx.frame, ctx.point_key(pixel), static_cast<uint32_t>(n + i), s.sampler);
          const Vec2 offset = samples.get2(SamplePurpose::kPixel, 0, 0);
          batch.add(CameraSample{static_cast<float>(x) + offset.x, static_cast<float>(y) + offset.y, samples, 1.0f}, 0);
        }
        batch.trace(ctx);
        for (int i = 0; i < batch.count; ++i) {
          Vec3 value = batch.radiance[i];
          if (!is_finite(value) || std::min(value.x, std::min(value.y, value.z)) < 0.0f) {
            ++ctx.counters.invalid_samples;
            value = Vec3(0.0f);
          }
          const float peak = max_component(value);
          if (settings_.clamp > 0.0f && peak > settings_.clamp) value *= settings_.clamp / peak;
          sum += value;
          if (ctx.aovs) layers.add(batch.aovs[i], 1.0f);
          const double l = (value.x + value.y + value.z) / 3.0;
          luminance += l;
          luminance_squares += l * l;
        }
        n += batch.count;
        batch.clear();
        if (settings_.noise_threshold > 0.0f && n >= kMinSamples && n < spp &&
            pixel_relative_error(luminance, luminance_squares, n) < settings_.noise_threshold)
          break;
      }
      layers.albedo /= static_cast<float>(n);
      layers.normal /= static_cast<float>(n);
      layers.emission /= static_cast<float>(n);
      out.at(x, y) = FilmPixel{sum / static_cast<float>(n), static_cast<uint16_t>(n), 0, layers,
                               mean_variance(luminance, luminance_squares, n)};
    }
    ctx.row_done(tile.width());
  }
  return true;
}

}  // namespace rt
