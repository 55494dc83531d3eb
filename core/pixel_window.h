// A rectangle of an image's pixels, [x0, x1) x [y0, y1): what one render computes when it renders
// part of the image (--crop, --tile), in the whole image's coordinates. A pixel's value does not
// depend on the window it is rendered in.
#pragma once

#include <cstdint>

namespace rt {

struct PixelWindow {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  static PixelWindow whole(int width, int height) { return PixelWindow{0, 0, width, height}; }
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  uint64_t pixels() const { return empty() ? 0 : static_cast<uint64_t>(width()) * static_cast<uint64_t>(height()); }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  // Whether it lies inside a width x height image.
  bool inside(int width, int height) const { return x0 >= 0 && y0 >= 0 && x1 <= width && y1 <= height; }
  bool operator==(const PixelWindow&) const = default;
};

}  // namespace rt
