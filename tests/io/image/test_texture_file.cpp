// Texture files: every PNG sample layout stb_image reads (8 and 16 bits; grey, grey + alpha, RGB,
// RGBA), sRGB decoding of colour textures only, and located errors for bad files.
#include <zlib.h>

#include <cstring>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/color.h"
#include "io/image/png_file.h"
#include "io/image/texture_file.h"
#include "tests/support/test_paths.h"
#include "tools/textures/patterns.h"

using namespace rt;

namespace {

void put32(std::vector<uint8_t>& out, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<uint8_t>(v >> s));
}

void chunk(std::vector<uint8_t>& out, const char* type, const std::vector<uint8_t>& data) {
  put32(out, static_cast<uint32_t>(data.size()));
  std::vector<uint8_t> body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  out.insert(out.end(), body.begin(), body.end());
  put32(out, static_cast<uint32_t>(crc32(0, body.data(), static_cast<uInt>(body.size()))));
}

// A PNG of w x h pixels, `channels` samples each (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA) of
// `depth` bits, sample k of the image being samples[k] (big-endian for 16 bits).
std::string png(int w, int h, int channels, int depth, const std::vector<uint16_t>& samples) {
  static constexpr uint8_t kColorType[] = {0, 0, 4, 2, 6};
  std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<uint8_t> ihdr;
  put32(ihdr, static_cast<uint32_t>(w));
  put32(ihdr, static_cast<uint32_t>(h));
  ihdr.insert(ihdr.end(), {static_cast<uint8_t>(depth), kColorType[channels], 0, 0, 0});
  chunk(out, "IHDR", ihdr);
  std::vector<uint8_t> raw;
  size_t k = 0;
  for (int y = 0; y < h; ++y) {
    raw.push_back(0);  // filter: none
    for (int i = 0; i < w * channels; ++i, ++k) {
      if (depth == 16) raw.push_back(static_cast<uint8_t>(samples[k] >> 8));
      raw.push_back(static_cast<uint8_t>(samples[k]));
    }
  }
  std::vector<uint8_t> packed(compressBound(static_cast<uLong>(raw.size())));
  uLongf size = static_cast<uLongf>(packed.size());
  REQUIRE(compress(packed.data(), &size, raw.data(), static_cast<uLong>(raw.size())) == Z_OK);
  packed.resize(size);
  chunk(out, "IDAT", packed);
  chunk(out, "IEND", {});
  return std::string(out.begin(), out.end());
}

// Limits with `texels` for one image and the default budget for all.
LoadLimits limits_of(uint64_t texels) {
  LoadLimits limits;
  limits.texture_texels = texels;
  return limits;
}

// What load_texture says about a file: empty when it loads.
std::string load_error(const std::string& path, TextureEncoding encoding = TextureEncoding::kSrgb,
                       uint64_t texels = uint64_t{1} << 20) {
  LimitUsage usage;
  TextureError error;
  const auto t = load_texture(path, encoding, limits_of(texels), usage, error);
  if (t) return "";
  CHECK_FALSE(error.message.empty());
  return error.message;
}

Texture load(const std::string& name, const std::string& bytes, TextureEncoding encoding) {
  const std::string path = rt::test::write_file(name, bytes);
  LimitUsage usage;
  TextureError error;
  auto t = load_texture(path, encoding, limits_of(uint64_t{1} << 20), usage, error);
  INFO(error.message);
  REQUIRE(t);
  return std::move(*t);
}

}  // namespace

TEST_CASE("sRGB decoding of known values", "[texture][io]") {
  CHECK(srgb_decode(0.0f) == 0.0f);
  CHECK(srgb_decode(1.0f) == Approx(1.0f));
  CHECK(srgb_decode(10.0f / 255) == Approx(10.0f / 255 / 12.92f));    // the linear segment
  CHECK(srgb_decode(188.0f / 255) == Approx(0.5029f).epsilon(1e-3));  // 188 encodes 0.5
  CHECK(srgb_decode(0.5f) == Approx(0.21404f).epsilon(1e-4));
  for (int v = 0; v < 256; ++v) CHECK(srgb8(srgb_decode(static_cast<float>(v) / 255)) == v);  // round trip
}

TEST_CASE("texture files: 8 and 16 bits, grey, grey + alpha, RGB, RGBA, sRGB or linear", "[texture][io]") {
  // Two texels: (188, 0, 255) then (0, 64, 255) as RGB; grey files hold 188 then 64.
  const Texture rgb = load("tex_rgb8.png", png(2, 1, 3, 8, {188, 0, 255, 0, 64, 255}), TextureEncoding::kSrgb);
  CHECK(rgb.width() == 2);
  CHECK(rgb.texel(0, 0).x == Approx(srgb_decode(188.0f / 255)));
  CHECK(rgb.texel(0, 0).z == Approx(1.0f));
  CHECK(rgb.texel(1, 0).y == Approx(srgb_decode(64.0f / 255)));
  const Texture rgba = load("tex_rgba8.png", png(2, 1, 4, 8, {188, 0, 255, 7, 0, 64, 255, 9}), TextureEncoding::kSrgb);
  CHECK(rgba.texel(1, 0).y == Approx(srgb_decode(64.0f / 255)));
  const Texture grey = load("tex_grey8.png", png(2, 1, 1, 8, {188, 64}), TextureEncoding::kLinear);
  CHECK(grey.texel(0, 0).x == Approx(188.0f / 255));  // a height map: not decoded
  CHECK(grey.texel(0, 0).z == Approx(188.0f / 255));
  const Texture grey_alpha = load("tex_ga8.png", png(2, 1, 2, 8, {188, 1, 64, 2}), TextureEncoding::kLinear);
  CHECK(grey_alpha.texel(1, 0).y == Approx(64.0f / 255));
  const Texture grey16 = load("tex_grey16.png", png(2, 1, 1, 16, {65535, 32768}), TextureEncoding::kLinear);
  CHECK(grey16.texel(1, 0).x == Approx(32768.0f / 65535));  // more levels than 8 bits hold
  const Texture rgb16 =
      load("tex_rgb16.png", png(1, 2, 3, 16, {65535, 0, 32768, 0, 1000, 65535}), TextureEncoding::kSrgb);
  CHECK(rgb16.height() == 2);
  CHECK(rgb16.texel(0, 0).z == Approx(srgb_decode(32768.0f / 65535)));
  CHECK(rgb16.texel(0, 1).y == Approx(srgb_decode(1000.0f / 65535)));
}

TEST_CASE("texture files: missing, not an image, zero-sized or too large are errors", "[texture][io]") {
  CHECK_THAT(load_error(rt::test::output_path("no_such_texture.png")),
             Catch::Contains("no_such_texture.png") && Catch::Contains("file not found"));

  const std::string text = rt::test::write_file("not_an_image.png", "hello, I am text");
  CHECK_THAT(load_error(text), Catch::Contains("expected a PNG, JPEG or WebP image, found neither (it starts with the "
                                               "bytes 68 65 6c 6c) in \"" +
                                               text + "\""));

  const std::string big = rt::test::write_file("tex_big.png", png(64, 64, 1, 8, std::vector<uint16_t>(64 * 64, 9)));
  CHECK_THAT(load_error(big, TextureEncoding::kLinear, 1000),
             Catch::Contains("expected an image of at most 1000 texels in \"" + big + "\", found 64 x 64 (4096)"));

  const std::string empty = rt::test::write_file("tex_zero.png", png(0, 0, 1, 8, {}));
  CHECK_THAT(load_error(empty, TextureEncoding::kLinear, 1000),
             Catch::Contains("expected a PNG of 1 to 2^31 - 1 pixels a side, found 0 x 0"));
}

TEST_CASE("make_textures: the checked-in example textures are exactly what the generator makes", "[texture][tools]") {
  for (const textures::Pattern& p : textures::patterns()) {
    INFO(p.file);
    std::string error;
    const auto stored = read_png(rt::test::source_path("scenes/textures/" + p.file), error);
    REQUIRE(stored);
    const Rgb8Image generated = textures::render_pattern(p);
    CHECK(stored->width == generated.width);
    CHECK(stored->height == generated.height);
    CHECK(stored->rgb == generated.rgb);
  }
}

TEST_CASE("make_textures: the tiled example textures have no seam where they repeat", "[texture][tools]") {
  // Across the wrap (last column to first, last row to first) a texture that tiles changes no
  // more than between neighbours inside it; a seam shows as a jump several times larger.
  for (const char* file : {"wood.png", "checker.png", "bricks.png", "bricks_colour.png", "bricks_normal.png"}) {
    INFO(file);
    std::string error;
    const auto img = read_png(rt::test::source_path(std::string("scenes/textures/") + file), error);
    REQUIRE(img);
    const int w = static_cast<int>(img->width), h = static_cast<int>(img->height);
    const auto at = [&](int x, int y, int c) {
      return static_cast<double>(
          img->rgb[(static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * 3 +
                   static_cast<size_t>(c)]);
    };
    const auto column_step = [&](int x0, int x1) {
      double sum = 0;
      for (int y = 0; y < h; ++y)
        for (int c = 0; c < 3; ++c) sum += std::fabs(at(x0, y, c) - at(x1, y, c));
      return sum / (3.0 * h);
    };
    const auto row_step = [&](int y0, int y1) {
      double sum = 0;
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) sum += std::fabs(at(x, y0, c) - at(x, y1, c));
      return sum / (3.0 * w);
    };
    double inside_x = 0, inside_y = 0;
    for (int x = 0; x + 1 < w; ++x) inside_x = std::max(inside_x, column_step(x, x + 1));
    for (int y = 0; y + 1 < h; ++y) inside_y = std::max(inside_y, row_step(y, y + 1));
    CHECK(column_step(w - 1, 0) <= inside_x + 0.5);
    CHECK(row_step(h - 1, 0) <= inside_y + 0.5);
  }
}
