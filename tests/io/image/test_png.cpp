// 8-bit output: the sRGB table against its formula, and the zlib PNG encoder read back by stb.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include <catch2/catch.hpp>

#include "core/color.h"
#include "core/rng.h"
#include "io/image/png_encoder.h"
#include "io/image/png_file.h"
#include "io/image/rgb8_image.h"
#include "tests/support/test_paths.h"

using namespace rt;

TEST_CASE("sRGB table encodes exactly as the formula", "[io][png]") {
  // Every 4099th float in [0, 1] with its neighbours, and a million random ones.
  bool seen[256] = {};
  for (uint32_t bits = 0; bits <= 0x3f800000u; bits += 4099) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    REQUIRE(srgb8(f) == srgb8_by_formula(f));
    const float below = std::nextafter(f, 0.0f), above = std::nextafter(f, 2.0f);
    REQUIRE(srgb8(below) == srgb8_by_formula(below));
    REQUIRE(srgb8(above) == srgb8_by_formula(above));
    seen[srgb8(f)] = true;
  }
  CHECK(std::count(std::begin(seen), std::end(seen), true) == 256);  // every level was reached
  Rng rng(3);
  for (int i = 0; i < 1'000'000; ++i) {
    const float f = rng.next_float() * 1.2f - 0.1f;
    REQUIRE(srgb8(f) == srgb8_by_formula(f));
  }
  // The first float of each bucket of the table (bits >> 14), whose code it holds.
  for (uint32_t bits = 0; bits <= 0x3f800000u; bits += 1u << 14) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    REQUIRE(srgb8(f) == srgb8_by_formula(f));
  }
  CHECK(srgb8(0.5f) == 188);  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354 -> 187.5 -> 188
  CHECK(srgb8(0.0031308f) == 10);
  CHECK(srgb8(INFINITY) == 255);
  CHECK(srgb8(-INFINITY) == 0);
}

TEST_CASE("PNG encoder: read back equal, bytes independent of the thread count", "[io][png]") {
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{37, 64}, std::pair{200, 131}, std::pair{3, 300}}) {
    INFO(w << "x" << h);
    Rgb8Image image{w, h, ZeroedVector<uint8_t>(static_cast<size_t>(w) * static_cast<size_t>(h) * 3)};
    Rng rng(static_cast<uint64_t>(w * h));
    for (size_t i = 0; i < image.rgb.size(); ++i)  // gradients with noise: exercises Sub filtering
      image.rgb[i] = static_cast<uint8_t>((i / 3 % static_cast<size_t>(w)) * 2 + i % 3 * 40 + (rng.next_u32() & 7));
    const std::vector<uint8_t> one = encode_png(image, 1);
    REQUIRE(one.size() > 40);
    CHECK(encode_png(image, 2) == one);
    CHECK(encode_png(image, 7) == one);
    std::string error;
    const std::string path = rt::test::output_path("encoder.png");
    REQUIRE(write_png(path, image, error, 3));
    const auto back = read_png(path, error);
    REQUIRE(back);
    CHECK(back->width == w);
    CHECK(back->height == h);
    CHECK(back->rgb == image.rgb);
  }
}

TEST_CASE("PNG encoder: a render's rows encoded band by band give the bytes of its whole 8-bit image", "[io][png]") {
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{37, 64}, std::pair{200, 131}}) {
    Image linear(w, h);
    Rng rng(static_cast<uint64_t>(w + 7 * h));
    for (Vec3& p : linear.pixels) p = Vec3(rng.next_float() * 1.5f, rng.next_float(), rng.next_float() * 4.0f - 1.0f);
    linear.pixels[0] = Vec3(NAN, INFINITY, -INFINITY);
    DisplayTransform filmic;
    filmic.exposure = 0.7f;
    filmic.curve = ToneMap::kFilmic;
    for (const DisplayTransform& display : {DisplayTransform{}, filmic}) {
      INFO(w << "x" << h << (display.identity() ? "" : ", filmic +0.7"));
      const std::vector<uint8_t> whole = encode_png(encode_srgb8(linear, display, 2), 1);
      CHECK(encode_png(srgb8_rows(linear, display), 1) == whole);
      CHECK(encode_png(srgb8_rows(linear, display), 3) == whole);
      std::string error;
      const std::string path = rt::test::output_path("rows.png");
      REQUIRE(write_png(path, srgb8_rows(linear, display), error, 2));
      const auto back = read_png(path, error);
      REQUIRE(back);
      CHECK(back->rgb == encode_srgb8(linear, display).rgb);
    }
  }
}
