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

FilmPixel PathSampler::sample_pixel(int x, int y, PixelState& state, int end, PixelContext& ctx) const {
  const int spp = std::max(1, settings_.samples_per_pixel);
  CameraBatch batch;
  const SampleStream::PointKey pixel = batch.key(ctx, ctx.pixel_point(x, y));
  int& n = state.n;
  while (!state.stopped && n < std::min(end, spp)) {
    const int count = std::min(kPacketSize, spp - n);
    for (int i = 0; i < count; ++i) {
      CameraSample& c = batch.add(ctx, pixel, static_cast<uint32_t>(n + i), 0);
      const Vec2 offset = c.samples.get2(SamplePurpose::kPixel, 0, 0);
      c.px = static_cast<float>(x) + offset.x;
      c.py = static_cast<float>(y) + offset.y;
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
      state.sum += value;
      if (ctx.aovs) state.layers.add(batch.aovs[i], 1.0f);
      const double l = (value.x + value.y + value.z) / 3.0;
      state.luminance += l;
      state.luminance_squares += l * l;
    }
    n += batch.count;
    batch.clear();
    if (settings_.noise_threshold > 0.0f && n >= kMinSamples && n < spp &&
        pixel_relative_error(state.luminance, state.luminance_squares, n) < settings_.noise_threshold)
      state.stopped = true;
  }
  Aovs layers = state.layers;
  layers.albedo /= static_cast<float>(n);
  layers.normal /= static_cast<float>(n);
  layers.emission /= static_cast<float>(n);
  return FilmPixel{state.sum / static_cast<float>(n), static_cast<uint16_t>(n), 0, layers,
                   mean_variance(state.luminance, state.luminance_squares, n)};
}

bool PathSampler::resume(SampleState state, const PixelWindow& window) {
  if (state.size() != window.pixels()) return false;
  window_ = window;
  states_ = std::move(state);
  // A pixel that one render of all the samples would have stopped where the earlier render
  // ended (its last check came at its own last sample, which was not a check) stops now.
  const int spp = std::max(1, settings_.samples_per_pixel);
  for (PixelState& p : states_)
    if (settings_.noise_threshold > 0.0f && !p.stopped && p.n >= kMinSamples && p.n < spp &&
        pixel_relative_error(p.luminance, p.luminance_squares, p.n) < settings_.noise_threshold)
      p.stopped = true;
  return true;
}

int PathSampler::resumed_samples() const {
  int fewest = 0;
  bool any = false;
  for (const PixelState& p : states_)
    if (!p.stopped && p.n < settings_.samples_per_pixel) {
      fewest = any ? std::min(fewest, p.n) : p.n;
      any = true;
    }
  return fewest;
}

bool PathSampler::begin_pass(int samples_end, const PixelWindow& window) {
  if (states_.empty()) {
    window_ = window;
    states_.assign(window.pixels(), PixelState{});
  }
  pass_end_ = samples_end;
  for (const PixelState& p : states_)
    if (!p.stopped && p.n < std::min(samples_end, std::max(1, settings_.samples_per_pixel))) return true;
  return false;  // every pixel has all it will take
}

bool PathSampler::render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) {
  for (int y = tile.y0; y < tile.y1; ++y) {
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (ctx.cancelled()) return false;
      if (states_.empty()) {
        PixelState state;
        out.at(x, y) = sample_pixel(x, y, state, settings_.samples_per_pixel, ctx);
      } else {
        const size_t i = static_cast<size_t>(y - window_.y0) * static_cast<size_t>(window_.width()) +
                         static_cast<size_t>(x - window_.x0);
        out.at(x, y) = sample_pixel(x, y, states_[i], pass_end_, ctx);
      }
    }
    ctx.row_done(tile.width());
  }
  return true;
}

}  // namespace rt
