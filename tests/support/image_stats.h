// What the path tracer's statistical tests measure of an image: its mean with the standard error
// over its pixels, and the RMS difference between two images; and a render to an Image in one call.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/image.h"
#include "core/render/renderer.h"
#include "io/scene_loader.h"

namespace rt::test {

struct Stats {
  double mean = 0.0;
  double error = 0.0;  // standard error of the mean over pixels
};

// The mean of the pixels' channel averages.
inline Stats image_stats(const Image& image) {
  double sum = 0.0, squares = 0.0;
  const double n = static_cast<double>(image.pixels.size());
  for (const Vec3& p : image.pixels) {
    const double v = (p.x + p.y + p.z) / 3.0;
    sum += v;
    squares += v * v;
  }
  const double mean = sum / n;
  return Stats{mean, std::sqrt(std::max(0.0, squares / n - mean * mean) / n)};
}

inline Image render_image(const LoadedScene& s, const RenderSettings& settings, RenderStats* stats = nullptr) {
  Image image;
  const RenderStats r = render(s.scene, settings, image);
  if (stats) *stats = r;
  return image;
}

inline double rmse(const Image& a, const Image& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const Vec3 d = a.pixels[i] - b.pixels[i];
    sum += glm::dot(d, d) / 3.0;
  }
  return std::sqrt(sum / static_cast<double>(a.pixels.size()));
}

}  // namespace rt::test
