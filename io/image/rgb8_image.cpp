#include "io/image/rgb8_image.h"

#include <vector>

#include "core/color.h"

namespace rt {

Rgb8Image encode_srgb8(const Image& image, const DisplayTransform& display) {
  Rgb8Image out{image.width, image.height, std::vector<uint8_t>(image.pixels.size() * 3)};
  uint8_t* dst = out.rgb.data();
  const bool identity = display.identity();
  for (const Vec3& linear : image.pixels) {
    const Vec3 p = identity ? linear : display.apply(linear);
    *dst++ = srgb8(p.x);
    *dst++ = srgb8(p.y);
    *dst++ = srgb8(p.z);
  }
  return out;
}

}  // namespace rt
