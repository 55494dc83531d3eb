#include "io/image/rgb8_image.h"

#include <cmath>
#include <vector>

#include "core/color.h"
#include "io/image/view_transform.h"

namespace rt {

Rgb8Image encode_srgb8(const Image& image, const DisplayTransform& display) {
  Rgb8Image out{image.width, image.height, std::vector<uint8_t>(image.pixels.size() * 3)};
  uint8_t* dst = out.rgb.data();
  const bool identity = display.identity();
  const Srgb8Table& codes = srgb8_table();
  for (const Vec3& linear : image.pixels) {
    const Vec3 p = identity ? linear : display.apply(linear);
    *dst++ = codes.encode(p.x);
    *dst++ = codes.encode(p.y);
    *dst++ = codes.encode(p.z);
  }
  return out;
}

Rgb8Image encode_display8(const Image& image, const DisplayTransform& display, const ViewTransform* view) {
  if (!view) return encode_srgb8(image, display);
  std::vector<Vec3> pixels = image.pixels;
  if (display.exposure != 0.0f)
    for (Vec3& p : pixels) p *= std::exp2(display.exposure);
  view->apply(pixels);
  Rgb8Image out{image.width, image.height, std::vector<uint8_t>(pixels.size() * 3)};
  uint8_t* dst = out.rgb.data();
  for (const Vec3& p : pixels)
    for (int c = 0; c < 3; ++c) *dst++ = static_cast<uint8_t>(std::lround(p[c] * 255.0f));
  return out;
}

}  // namespace rt
