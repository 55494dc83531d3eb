// A float RGB image in linear colour: what the renderer writes and the image writers encode.
#pragma once

#include <vector>

#include "core/math.h"

namespace rt {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Vec3> pixels;  // row-major, row 0 at the top

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * static_cast<size_t>(h), Vec3(0.0f)) {}

  Vec3& at(int x, int y) {
    return pixels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
  }
  const Vec3& at(int x, int y) const {
    return pixels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
  }
};

}  // namespace rt
