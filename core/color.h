// Colour encodings shared by the renderer and the image writers.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace rt {

// The sRGB transfer function of a linear value clamped to [0, 1] (NaN counts as 0): what a
// display shows, in [0, 1]. 8-bit output rounds it to 256 levels (io/rgb8_image.h).
inline float srgb_encode(float linear) {
  const float c = std::isnan(linear) ? 0.0f : std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

inline Vec3 srgb_encode(const Vec3& linear) {
  return Vec3(srgb_encode(linear.x), srgb_encode(linear.y), srgb_encode(linear.z));
}

}  // namespace rt
