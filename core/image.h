// A float RGB image in linear colour: what the renderer writes and the image writers encode.
#pragma once

#include <vector>

#include "core/math.h"
#include "core/zeroed_vector.h"

namespace rt {

struct Image {
  int width = 0;
  int height = 0;
  ZeroedVector<Vec3> pixels;  // row-major, row 0 at the top; new pixels are zero without being written

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * static_cast<size_t>(h)) {}

  Vec3& at(int x, int y) {
    return pixels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
  }
  const Vec3& at(int x, int y) const {
    return pixels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
  }
};

}  // namespace rt
