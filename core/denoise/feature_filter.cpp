#include "core/denoise/feature_filter.h"

#include <algorithm>
#include <cmath>

#include "core/parallel_for.h"

namespace rt {
namespace {

constexpr float kKernel[5] = {1.0f / 16.0f, 1.0f / 4.0f, 3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};

float luminance(Vec3 c) { return (c.x + c.y + c.z) / 3.0f; }  // as the path sampler's variance

// What the passes read of each pixel beyond the input's layers: whether the camera met a surface
// there (a normal was recorded), and how fast depth changes per pixel (the larger of x and y).
struct Guide {
  std::vector<bool> hit;
  std::vector<float> slope;
};

Guide make_guide(const DenoiseInput& in) {
  const int width = in.color.width, height = in.color.height;
  const size_t n = in.color.pixels.size();
  Guide g;
  g.hit.resize(n);
  g.slope.assign(n, 0.0f);
  for (size_t i = 0; i < n; ++i) g.hit[i] = glm::dot(in.normal.pixels[i], in.normal.pixels[i]) > 0.0f;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
      if (!g.hit[i]) continue;
      // The smaller one-sided difference on each axis: a silhouette beside the pixel is no slope.
      const auto along = [&](int dx, int dy) {
        float best = kInfinity;
        for (const int s : {-1, 1}) {
          const int qx = x + s * dx, qy = y + s * dy;
          if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
          const size_t j = static_cast<size_t>(qy) * static_cast<size_t>(width) + static_cast<size_t>(qx);
          if (g.hit[j]) best = std::min(best, std::fabs(in.depth[j] - in.depth[i]));
        }
        return best < kInfinity ? best : 0.0f;
      };
      g.slope[i] = std::max(along(1, 0), along(0, 1));
    }
  return g;
}

}  // namespace

Image FeatureFilter::denoise(const DenoiseInput& in, unsigned threads) const {
  const int width = in.color.width, height = in.color.height;
  const size_t n = in.color.pixels.size();
  const Guide g = make_guide(in);

  // 1. Demodulate: the light arriving, and its variance in the same units.
  std::vector<Vec3> divisor(n, Vec3(1.0f)), light(n);
  std::vector<float> variance(n);
  for (size_t i = 0; i < n; ++i) {
    if (g.hit[i]) divisor[i] = glm::max(in.albedo.pixels[i], Vec3(kAlbedoFloor));
    // (What a bounce made is never negative; a rounding step below the emission is dropped.)
    light[i] = glm::max(in.color.pixels[i] - in.emission.pixels[i], Vec3(0.0f)) / divisor[i];
    const float scale = 1.0f / luminance(divisor[i]);
    const float v = in.variance.empty() ? 0.0f : in.variance[i] * scale * scale;
    variance[i] = std::isfinite(v) && v > 0.0f ? v : 0.0f;  // a hostile layer: no noise, not NaN
    if (!is_finite(light[i])) light[i] = Vec3(0.0f);
  }

  // 2. The passes, each reading the last one's light and variance.
  std::vector<Vec3> next_light(n);
  std::vector<float> next_variance(n);
  for (int pass = 0; pass < kPasses; ++pass) {
    const int step = 1 << pass;
    parallel_for(static_cast<size_t>(height), threads, 4, [&](unsigned, size_t row) {
      const int y = static_cast<int>(row);
      for (int x = 0; x < width; ++x) {
        const size_t i = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
        // The noise's standard deviation here: the variance blurred over 3x3 (one pixel's own is noisy too).
        float blurred = 0.0f, blur_weight = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
            const float w = kKernel[dx + 2] * kKernel[dy + 2];
            blurred += w * variance[static_cast<size_t>(qy) * static_cast<size_t>(width) + static_cast<size_t>(qx)];
            blur_weight += w;
          }
        const float sigma = kLuminanceSigma * std::sqrt(blurred / blur_weight) + 1e-6f;
        const float lum = luminance(light[i]);
        Vec3 sum(0.0f);
        float weights = 0.0f, variance_sum = 0.0f;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) {
            const int qx = x + dx * step, qy = y + dy * step;
            if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
            const size_t j = static_cast<size_t>(qy) * static_cast<size_t>(width) + static_cast<size_t>(qx);
            if (g.hit[i] != g.hit[j]) continue;
            float w = kKernel[dx + 2] * kKernel[dy + 2];
            if (j != i) {
              w *= std::exp(-std::fabs(luminance(light[j]) - lum) / sigma);
              if (g.hit[i]) {
                w *= std::pow(std::max(0.0f, glm::dot(in.normal.pixels[i], in.normal.pixels[j])), kNormalPower);
                const float reach = kDepthSigma * g.slope[i] * static_cast<float>(step) *
                                        std::sqrt(static_cast<float>(dx * dx + dy * dy)) +
                                    1e-3f * in.depth[i];
                w *= std::exp(-std::fabs(in.depth[j] - in.depth[i]) / reach);
                const Vec3 da = in.albedo.pixels[j] - in.albedo.pixels[i];
                w *= std::exp(-glm::dot(da, da) / (2.0f * kAlbedoSigma * kAlbedoSigma));
              }
            }
            if (!(w > 0.0f)) continue;
            sum += w * light[j];
            weights += w;
            variance_sum += w * w * variance[j];
          }
        next_light[i] = sum / weights;  // the pixel's own tap keeps weights > 0
        next_variance[i] = variance_sum / (weights * weights);
      }
    });
    light.swap(next_light);
    variance.swap(next_variance);
  }

  // 3. Remodulate.
  Image out(width, height);
  for (size_t i = 0; i < n; ++i) out.pixels[i] = light[i] * divisor[i] + in.emission.pixels[i];
  return out;
}

}  // namespace rt
