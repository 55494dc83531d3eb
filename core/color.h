// Colour encodings shared by the renderer and the image writers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/math.h"

namespace rt {

// The sRGB transfer function of a linear value clamped to [0, 1] (NaN counts as 0): what a
// display shows, in [0, 1]. 8-bit output rounds it to 256 levels (io/image/rgb8_image.h).
inline float srgb_encode(float linear) {
  const float c = std::isnan(linear) ? 0.0f : std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// The inverse: a displayed (sRGB-encoded) value in [0, 1] to linear. Colour textures are stored
// encoded and decoded with this when loaded.
inline float srgb_decode(float encoded) {
  const float c = std::isnan(encoded) ? 0.0f : std::clamp(encoded, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// The 8-bit code of srgb_encode(linear), rounded to the nearest of 256 levels: what a PNG holds.
// Through an exact table (a code per bucket of floats plus one comparison, no pow); tests check
// it against srgb8_by_formula for every level.
uint8_t srgb8(float linear);
uint8_t srgb8_by_formula(float linear);

}  // namespace rt
