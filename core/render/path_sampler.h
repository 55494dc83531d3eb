// The path tracer's pixel sampler: up to render.samples_per_pixel camera samples per pixel, each
// through a keyed random point of the pixel (a box filter), averaged. With render.noise_threshold
// a pixel stops early once its estimated relative error is below the threshold:
//   error = standard error of the mean luminance / max(mean luminance, kNoiseFloor),
// checked after every packet of samples once kMinSamples are in. A pixel's samples and its stop
// depend only on its own keys, so the image is the same for any thread count or tile order.
// Each sample's radiance passes render.clamp (if set) and the check that drops anything but a
// finite, non-negative colour (counted in RayCounters::invalid_samples). The first-hit layers,
// when asked, average the same samples (core/render/aovs.h).
#pragma once

#include "core/render/pixel_sampler.h"
#include "core/render/sample_sums.h"

namespace rt {

class PathSampler final : public PixelSampler {
 public:
  static constexpr int kMinSamples = 16;
  // Below this mean luminance the error is measured against it rather than the mean: dark pixels
  // need not be known to a percent of almost nothing (0.02 is 0.15 after sRGB encoding).
  static constexpr float kNoiseFloor = 0.02f;

  explicit PathSampler(const PathSettings& settings) : settings_(settings) {}
  bool render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) override;

  // Progressive rendering: each pass adds samples up to `samples_end` to every pixel of `window`
  // that still takes them, from the sums the passes before it left, in the same order as one
  // render of all the samples: the pixels come out the same bits.
  bool renders_passes() const override { return true; }
  bool begin_pass(int samples_end, const PixelWindow& window) override;

  bool resume(SampleState state, const PixelWindow& window) override;
  int resumed_samples() const override;
  const SampleState* sums() const override { return states_.empty() ? nullptr : &states_; }

  using PixelState = SampleSums;

 private:
  // Adds samples to the pixel up to `end` (fewer if the noise threshold stops it); its film value.
  FilmPixel sample_pixel(int x, int y, PixelState& state, int end, PixelContext& ctx) const;

  PathSettings settings_;
  // Passes: the pixels' states, row-major over the window, and where this pass stops.
  SampleState states_;
  PixelWindow window_;
  int pass_end_ = 0;
};

// The variance of the mean of n samples whose luminances sum to `sum` and whose squares sum to
// `sum_squares` (0 for fewer than 2).
float mean_variance(double sum, double sum_squares, int n);

// The relative error of a pixel's mean from n samples whose luminances sum to `sum` and whose
// squares sum to `sum_squares` (PathSampler's rule).
float pixel_relative_error(double sum, double sum_squares, int n);

}  // namespace rt
