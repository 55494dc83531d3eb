#include "tools/thumbnail/shrink.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/color.h"

namespace rt {
namespace {

// For each output index, the input indices it covers with their weights (coverage fractions).
struct Tap {
  int index;
  float weight;
};

std::vector<std::vector<Tap>> footprints(int in, int out) {
  std::vector<std::vector<Tap>> taps(static_cast<size_t>(out));
  const double scale = static_cast<double>(in) / out;
  for (int o = 0; o < out; ++o) {
    const double a = o * scale, b = (o + 1) * scale;
    for (int i = static_cast<int>(std::floor(a)); i < std::min(in, static_cast<int>(std::ceil(b))); ++i) {
      const double cover = std::min<double>(b, i + 1) - std::max<double>(a, i);
      if (cover > 0) taps[static_cast<size_t>(o)].push_back({i, static_cast<float>(cover / scale)});
    }
  }
  return taps;
}

}  // namespace

Rgb8Image shrink_image(const Rgb8Image& image, int width) {
  if (width <= 0 || image.width <= width) return image;
  const int height =
      std::max(1, static_cast<int>(std::lround(static_cast<double>(image.height) * width / image.width)));
  const auto xs = footprints(image.width, width), ys = footprints(image.height, height);
  std::vector<float> linear(256);
  for (int v = 0; v < 256; ++v) linear[static_cast<size_t>(v)] = srgb_decode(static_cast<float>(v) / 255.0f);
  Rgb8Image out{width, height, ZeroedVector<uint8_t>(static_cast<size_t>(width) * static_cast<size_t>(height) * 3)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float sum[3] = {0, 0, 0};
      for (const Tap& ty : ys[static_cast<size_t>(y)]) {
        const size_t row = static_cast<size_t>(ty.index) * static_cast<size_t>(image.width);
        for (const Tap& tx : xs[static_cast<size_t>(x)]) {
          const uint8_t* p = &image.rgb[(row + static_cast<size_t>(tx.index)) * 3];
          const float w = ty.weight * tx.weight;
          for (int c = 0; c < 3; ++c) sum[c] += w * linear[p[c]];
        }
      }
      uint8_t* q = &out.rgb[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3];
      for (int c = 0; c < 3; ++c) q[c] = srgb8(sum[c]);
    }
  }
  return out;
}

}  // namespace rt
