#include "io/rgb8_image.h"

#include <algorithm>
#include <cmath>

namespace rt {

uint8_t encode_srgb8(float linear) {
  const float c = std::isnan(linear) ? 0.0f : std::clamp(linear, 0.0f, 1.0f);
  const float encoded = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<uint8_t>(std::lround(encoded * 255.0f));
}

Rgb8Image encode_srgb8(const Image& image) {
  Rgb8Image out{image.width, image.height, {}};
  out.rgb.reserve(image.pixels.size() * 3);
  for (const Vec3& p : image.pixels) {
    out.rgb.push_back(encode_srgb8(p.x));
    out.rgb.push_back(encode_srgb8(p.y));
    out.rgb.push_back(encode_srgb8(p.z));
  }
  return out;
}

}  // namespace rt
