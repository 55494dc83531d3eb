// tools/thumbnail: shrinking averages light, not sRGB codes, and keeps the aspect ratio.
#include <catch2/catch.hpp>

#include "core/color.h"
#include "tools/thumbnail/shrink.h"

namespace {

rt::Rgb8Image columns(int width, int height) {  // black and white columns, one pixel each
  rt::Rgb8Image image{width, height, rt::ZeroedVector<uint8_t>(static_cast<size_t>(width * height) * 3)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.rgb[static_cast<size_t>((y * width + x) * 3 + c)] = x % 2 ? 255 : 0;
  return image;
}

}  // namespace

TEST_CASE("thumbnail: halving black and white columns gives half the light, sRGB 188", "[tools][thumbnail]") {
  const rt::Rgb8Image small = rt::shrink_image(columns(8, 4), 4);
  REQUIRE(small.width == 4);
  REQUIRE(small.height == 2);
  // Linear 0.5 encodes to 187.5 -> 188; the sRGB-code average (127.5) would be far darker.
  CHECK(rt::srgb8(0.5f) == 188);
  for (uint8_t v : small.rgb) CHECK(v == 188);
}

TEST_CASE("thumbnail: a non-integer factor weighs pixels by the area they cover", "[tools][thumbnail]") {
  // 3 pixels (black, white, black) into 2: each output covers 1.5 inputs, one third of it white.
  rt::Rgb8Image image{3, 1, {0, 0, 0, 255, 255, 255, 0, 0, 0}};
  const rt::Rgb8Image small = rt::shrink_image(image, 2);
  REQUIRE(small.width == 2);
  REQUIRE(small.height == 1);  // 1 * 2 / 3 rounds to 1, never 0
  CHECK(small.rgb[0] == rt::srgb8(1.0f / 3.0f));
  CHECK(small.rgb[3] == rt::srgb8(1.0f / 3.0f));
}

TEST_CASE("thumbnail: an image no wider than asked comes back unchanged", "[tools][thumbnail]") {
  const rt::Rgb8Image image = columns(6, 2);
  CHECK(rt::shrink_image(image, 6).rgb == image.rgb);
  CHECK(rt::shrink_image(image, 100).width == 6);
}
