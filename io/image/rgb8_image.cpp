#include "io/image/rgb8_image.h"

#include <vector>

#include "core/color.h"

namespace rt {

Rgb8Image encode_srgb8(const Image& image) {
  Rgb8Image out{image.width, image.height, std::vector<uint8_t>(image.pixels.size() * 3)};
  uint8_t* dst = out.rgb.data();
  for (const Vec3& p : image.pixels) {
    *dst++ = srgb8(p.x);
    *dst++ = srgb8(p.y);
    *dst++ = srgb8(p.z);
  }
  return out;
}

}  // namespace rt
