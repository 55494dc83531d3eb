#include "io/image/rgb8_image.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/display_codes.h"
#include "core/parallel_for.h"
#include "io/image/view_transform.h"

namespace rt {

namespace {

// Pixels [begin, end) of `image` as 8-bit codes from dst on.
void encode_pixels(const Image& image, const DisplayTransform& display, size_t begin, size_t end, uint8_t* dst) {
  display_codes(image.pixels.data() + begin, end - begin, display, dst);
}

}  // namespace

Rgb8Image encode_srgb8(const Image& image, const DisplayTransform& display, unsigned threads) {
  Rgb8Image out{image.width, image.height, ZeroedVector<uint8_t>(image.pixels.size() * 3)};
  // In bands of rows on every thread: on one, a 1920x1440 render waited 4% of its time here.
  constexpr size_t kBand = 65536;  // pixels
  parallel_for((image.pixels.size() + kBand - 1) / kBand, threads, 1, [&](unsigned, size_t band) {
    const size_t begin = band * kBand, end = std::min(image.pixels.size(), begin + kBand);
    encode_pixels(image, display, begin, end, out.rgb.data() + 3 * begin);
  });
  return out;
}

Rgb8Rows rows_of(const Rgb8Image& image) {
  const size_t row_bytes = static_cast<size_t>(image.width) * 3;
  return {image.width, image.height,
          [&image, row_bytes](int y, uint8_t*) { return image.rgb.data() + static_cast<size_t>(y) * row_bytes; }};
}

Rgb8Rows srgb8_rows(const Image& image, const DisplayTransform& display) {
  const auto width = static_cast<size_t>(image.width);
  return {image.width, image.height, [&image, &display, width](int y, uint8_t* scratch) {
            encode_pixels(image, display, static_cast<size_t>(y) * width, static_cast<size_t>(y + 1) * width, scratch);
            return static_cast<const uint8_t*>(scratch);
          }};
}

Rgb8Image encode_display8(const Image& image, const DisplayTransform& display, const ViewTransform* view,
                          unsigned threads) {
  if (!view) return encode_srgb8(image, display, threads);
  std::vector<Vec3> pixels(image.pixels.begin(), image.pixels.end());
  if (display.exposure != 0.0f)
    for (Vec3& p : pixels) p *= std::exp2(display.exposure);
  view->apply(pixels);
  Rgb8Image out{image.width, image.height, ZeroedVector<uint8_t>(pixels.size() * 3)};
  uint8_t* dst = out.rgb.data();
  for (const Vec3& p : pixels)
    for (int c = 0; c < 3; ++c) *dst++ = static_cast<uint8_t>(std::lround(p[c] * 255.0f));
  return out;
}

}  // namespace rt
