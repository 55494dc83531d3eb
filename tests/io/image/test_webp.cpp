// WebP textures (glTF's EXT_texture_webp; libwebp): a lossless image decodes to its exact texels,
// a glTF texture shows the extension's image rather than its fallback, and damaged or animated
// files are refused with their reason.
#include <string>
#include <vector>

#include <webp/encode.h>
#include <catch2/catch.hpp>

#include "io/gltf/loader.h"
#include "io/image/texture_file.h"
#include "tests/support/gltf_files.h"
#include "tests/support/gltf_import.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

// A lossless WebP of w x h pixels, all of one colour.
std::string webp(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  std::vector<uint8_t> rgb;
  for (int i = 0; i < w * h; ++i) rgb.insert(rgb.end(), {r, g, b});
  uint8_t* out = nullptr;
  const size_t size = WebPEncodeLosslessRGB(rgb.data(), w, h, w * 3, &out);
  REQUIRE(size > 0);
  std::string bytes(reinterpret_cast<const char*>(out), size);
  WebPFree(out);
  return bytes;
}

std::optional<Texture> decode(const std::string& bytes, TextureError& error) {
  LimitUsage usage;
  return decode_texture(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()), "t.webp",
                        TextureEncoding::kLinear, LoadLimits{}, usage, error);
}

}  // namespace

TEST_CASE("WebP textures decode to their texels, damaged ones are refused", "[image][webp]") {
  TextureError error;
  const auto texture = decode(webp(5, 3, 255, 51, 0), error);
  INFO(error.message);
  REQUIRE(texture);
  CHECK(texture->texel(4, 2).x == 1.0f);
  CHECK(texture->texel(4, 2).y == Approx(0.2f));
  CHECK(texture->texel(0, 0).z == 0.0f);

  std::string damaged = webp(64, 64, 10, 20, 30);
  for (size_t i = 40; i < damaged.size(); ++i) damaged[i] = static_cast<char>(i * 7);
  CHECK_FALSE(decode(damaged, error));
  CHECK_THAT(error.message, Catch::Contains("WebP"));
  const std::string cut = webp(64, 64, 10, 20, 30).substr(0, 20);
  CHECK_FALSE(decode(cut, error));
  CHECK_THAT(error.message, Catch::Contains("WebP"));
}

TEST_CASE("EXT_texture_webp: the texture shows the extension's image, not its fallback", "[gltf][webp]") {
  std::string buffer = rt::test::square_positions();
  rt::test::append<float>(buffer, {0, 1, 1, 1, 1, 0, 0, 0});
  rt::test::append<uint16_t>(buffer, {0, 1, 2, 0, 2, 3});
  const std::string blue = webp(2, 2, 0, 0, 255);
  const std::string red_png =  // 1 x 1 red
      "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGP4z8AAAAMBAQDJ/pLvAAAAAElFTkSuQmCC";
  const Json doc = {
      {"extensionsUsed", {"EXT_texture_webp"}},
      {"extensionsRequired", {"EXT_texture_webp"}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", 0}}}}}}},
      {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
      {"textures", {{{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}}}},
      {"images",
       {{{"uri", std::string("data:image/png;base64,") + red_png}},
        {{"uri", "data:image/webp;base64," + rt::test::base64(blue)}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
        {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
        {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 12}}}}};
  rt::test::ImportProblems problems;
  LimitUsage usage;
  const auto model = rt::test::import_gltf(rt::test::write_gltf("webp.gltf", buffer, doc), std::nullopt, LoadLimits{},
                                           usage, problems);
  INFO(problems.message);
  REQUIRE(model);
  CHECK(problems.warnings.empty());
  REQUIRE(model->textures.size() == 1);
  const Vec3 texel = model->textures[0].texel(0, 0);
  CHECK(texel.z == 1.0f);  // blue: the WebP
  CHECK(texel.x == 0.0f);
}
