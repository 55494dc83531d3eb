// Colour encodings shared by the renderer and the image writers.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

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

// srgb8 by the formula itself (pow and rounding): what the table below is built from and tested
// against.
uint8_t srgb8_by_formula(float linear);

// threshold[v] = the smallest float whose code is at least v; first[i] = the code of the first
// float of bucket i, the floats sharing their top bits (bits >> kShift). A bucket spans at most
// 1/512 of its value, and the formula's codes never step twice that close together, so a code is
// first[bucket] plus one comparison: bit for bit the formula's result. Built once (srgb8_table);
// loops over many values fetch it once and encode inline (the adaptive sampler's lattice points:
// 4% of antialias.json's time went to calls).
class Srgb8Table {
 public:
  Srgb8Table();
  uint8_t encode(float linear) const {
    if (!(linear > 0.0f)) return 0;  // also NaN
    if (linear >= 1.0f) return 255;
    uint32_t bits;
    std::memcpy(&bits, &linear, sizeof bits);
    const uint8_t code = first_[bits >> kShift];
    return linear >= threshold_[code + 1u] ? static_cast<uint8_t>(code + 1) : code;
  }

 private:
  static constexpr int kShift = 14;
  std::array<float, 257> threshold_{};
  std::vector<uint8_t> first_;
};
const Srgb8Table& srgb8_table();

// The 8-bit code of srgb_encode(linear), rounded to the nearest of 256 levels: what a PNG holds.
// Through the exact table (a code per bucket of floats plus one comparison, no pow); tests check
// it against srgb8_by_formula for every level.
inline uint8_t srgb8(float linear) { return srgb8_table().encode(linear); }

}  // namespace rt
