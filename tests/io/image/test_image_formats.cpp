// Image formats: PNG and JPEG decode; every other format stb_image knew is refused by name before
// any decoder runs (tests/data/images/, made by make_images.py), and so are the hostile files
// issue 17 found (a 21-byte 16-bit PGM, a truncated RLE Radiance file, an 80-scan JPEG, a
// Huffman table of 257 codes). Each answer comes at once.
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "io/image/image_header.h"
#include "io/image/texture_file.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

std::string image_path(const std::string& name) { return rt::test::source_path("tests/data/images/" + name); }

struct Loaded {
  std::optional<Texture> texture;
  TextureError error;
  double seconds = 0.0;
};

Loaded load(const std::string& name, TextureEncoding encoding = TextureEncoding::kLinear, LoadLimits limits = {},
            LimitUsage usage = {}) {
  const auto start = std::chrono::steady_clock::now();
  Loaded out;
  out.texture = load_texture(image_path(name), encoding, limits, usage, out.error);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

TEST_CASE("image formats: PNG and JPEG variants decode to the pixels written", "[texture][io][images]") {
  for (const char* name : {"rgb8.png", "grey16.png", "rgba16.png", "palette.png", "interlaced.png", "baseline.jpg",
                           "progressive.jpg", "grey.jpg"}) {
    INFO(name);
    const Loaded l = load(name);
    INFO(l.error.message);
    REQUIRE(l.texture);
  }
  // make_images.py's PPM source: x * 5 + y * 3 + c * 60 per channel c (no wrap at 16 x 16). JPEG is lossy
  // (and its chroma halved): the mean error over the image stays small.
  for (const char* name : {"baseline.jpg", "progressive.jpg"}) {
    const Loaded jpeg = load(name);
    REQUIRE(jpeg.texture);
    CHECK(jpeg.texture->width() == 16);
    CHECK(jpeg.texture->height() == 16);
    double error = 0.0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x)
        for (int c = 0; c < 3; ++c)
          error += std::abs(jpeg.texture->texel(x, y)[c] - static_cast<float>(x * 5 + y * 3 + c * 60) / 255);
    CHECK(error / (16 * 16 * 3) < 0.02);
  }
  // The interlaced PNG's pixel (x, y), channel c is (3x * 37 + c * 37 + y * 11) % 256.
  const Loaded adam7 = load("interlaced.png");
  REQUIRE(adam7.texture);
  CHECK(adam7.texture->width() == 9);
  CHECK(adam7.texture->texel(5, 4).y == Approx(static_cast<float>((15 * 37 + 37 + 44) % 256) / 255));
}

TEST_CASE("image formats: every other format is refused by name, before decoding", "[texture][io][images]") {
  const std::vector<std::pair<const char*, const char*>> refused = {
      {"image.gif", "a GIF image"},
      {"image.bmp", "a BMP image"},
      {"image.psd", "a Photoshop (PSD) image"},
      {"image.hdr", "a Radiance HDR image"},
      {"truncated-rle.hdr", "a Radiance HDR image"},  // stb_image 2.27 loops forever on it
      {"image.ppm", "a Netpbm (PNM) image"},
      {"grey16.pgm", "a Netpbm (PNM) image"},       // stb_image 2.27 over-reads it
      {"huge-header.ppm", "a Netpbm (PNM) image"},  // its size overflows stb_image's int
      {"image.pic", "a Softimage PIC image"},
      {"image.tga", "a Truevision TGA image"},
  };
  for (const auto& [name, what] : refused) {
    INFO(name);
    const Loaded l = load(name);
    CHECK_FALSE(l.texture);
    CHECK_THAT(l.error.message,
               Catch::Contains(std::string("expected a PNG, JPEG or WebP image, found ") + what + " in \"") &&
                   Catch::Contains(name));
    CHECK(l.seconds < 1.0);
  }
}

TEST_CASE("image formats: JPEG scans and Huffman tables, and PNG chunks, are checked first", "[texture][io][images]") {
  const Loaded many = load("eighty-scans.jpg");
  CHECK_FALSE(many.texture);
  CHECK_THAT(many.error.message, Catch::Contains("expected a JPEG of at most 64 scans, found more"));
  const std::string table =
      rt::test::read_file(rt::test::source_path("tests/fuzz/regressions/texture/jpeg-huffman-table-of-257-codes"));
  std::string error;
  CHECK_FALSE(read_image_header(reinterpret_cast<const unsigned char*>(table.data()), table.size(), error));
  CHECK_THAT(error, Catch::Contains("Huffman tables of at most 256 codes each"));
  // stb_image 2.27 passes memcpy a null pointer for an empty first IDAT chunk (found by fuzzing).
  const std::string idat =
      rt::test::read_file(rt::test::source_path("tests/fuzz/regressions/texture/png-empty-first-idat"));
  CHECK_FALSE(read_image_header(reinterpret_cast<const unsigned char*>(idat.data()), idat.size(), error));
  CHECK_THAT(error, Catch::Contains("expected a PNG whose first IDAT chunk holds image data, found an empty one"));
  // A PNG's image data is inflated and counted before decoding, against the size its header gives.
  const Loaded bomb = load("inflates-too-far.png");
  CHECK_FALSE(bomb.texture);
  CHECK_THAT(bomb.error.message, Catch::Contains("expected a PNG whose image data inflates to the 4 bytes its 1 x 1 "
                                                 "pixels need, found more"));
  const std::string claims =
      rt::test::read_file(rt::test::source_path("tests/fuzz/regressions/texture/png-idat-claims-2-gib"));
  CHECK_FALSE(read_image_header(reinterpret_cast<const unsigned char*>(claims.data()), claims.size(), error));
  CHECK_THAT(error,
             Catch::Contains("expected a PNG whose IDAT chunks lie inside the file, found one of 1866865153 bytes"));
  // What the header says the data inflates to is what it does, interlaced or not: one 9 x 7 RGB
  // image in seven Adam7 passes takes 203 bytes with the filter bytes (counted by hand).
  for (const auto& [name, expected] : {std::pair{"interlaced.png", 203}, std::pair{"rgb8.png", 8 * (1 + 24)},
                                       std::pair{"grey16.png", 4 * (1 + 8)}, std::pair{"palette.png", 4 * (1 + 4)}}) {
    const std::string png = rt::test::read_file(image_path(name));
    const auto header = read_image_header(reinterpret_cast<const unsigned char*>(png.data()), png.size(), error);
    REQUIRE(header);
    CHECK(header->png_data == static_cast<uint64_t>(expected));
  }
  // The walk over a real progressive JPEG: 10 scans (libjpeg's default script for colour).
  const std::string progressive = rt::test::read_file(image_path("progressive.jpg"));
  const auto header =
      read_image_header(reinterpret_cast<const unsigned char*>(progressive.data()), progressive.size(), error);
  REQUIRE(header);
  CHECK(header->format == ImageFormat::kJpeg);
  CHECK(header->scans == 10);
  CHECK(header->width == 16);
}

TEST_CASE("image formats: the scene's texel budget is checked from the header, with what is left",
          "[texture][io][images]") {
  LoadLimits limits;
  limits.scene_texels = 100;  // an 8 x 8 image takes 64 + 16 + 4 + 1 = 85 with its mip levels
  CHECK(Texture::texels_with_mip_levels(8, 8) == 85);
  CHECK(Texture::texels_with_mip_levels(8192, 4096) == 44739243);
  LimitUsage usage;
  TextureError error;
  REQUIRE(load_texture(image_path("rgb8.png"), TextureEncoding::kSrgb, limits, usage, error));
  CHECK(usage.texels == 85);
  CHECK_FALSE(load_texture(image_path("rgb8.png"), TextureEncoding::kLinear, limits, usage, error));
  CHECK(error.over_budget);
  CHECK_THAT(error.message, Catch::Contains("(8 x 8, 85 texels with its mip levels) does not fit in the scene's "
                                            "texture budget: 85 of its 100 texels are taken"));
  CHECK(usage.texels == 85);  // nothing spent on a refusal
  limits.texture_texels = 63;
  error = {};
  CHECK_FALSE(load_texture(image_path("rgb8.png"), TextureEncoding::kSrgb, limits, usage, error));
  CHECK_FALSE(error.over_budget);
  CHECK_THAT(error.message,
             Catch::Contains("expected an image of at most 63 texels in") && Catch::Contains("found 8 x 8 (64)"));
}
