// The 8-bit codes a PNG holds for linear colours: each channel through the display transform
// (core/tone_map.h), then sRGB's 256 levels (srgb8, core/color.h). The one place that is done,
// whether a whole image is encoded for its file (io/image/rgb8_image.h) or each tile as the
// renderer stores it into a film that keeps only these codes (RenderView::display8).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/color.h"
#include "core/tone_map.h"

namespace rt {

// `count` colours from `linear` on, 3 * count bytes from `rgb` on.
inline void display_codes(const Vec3* linear, size_t count, const DisplayTransform& display, uint8_t* rgb) {
  const bool identity = display.identity();
  const Srgb8Table& codes = srgb8_table();
  for (size_t i = 0; i < count; ++i) {
    const Vec3 p = identity ? linear[i] : display.apply(linear[i]);
    *rgb++ = codes.encode(p.x);
    *rgb++ = codes.encode(p.y);
    *rgb++ = codes.encode(p.z);
  }
}

}  // namespace rt
