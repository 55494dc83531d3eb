// Limits checked before the work they bound (issue 17): a glTF file's images are sized from their
// headers and its meshes from their accessors' counts before anything is decoded or read; images
// on one source are decoded once; glTF channels share their sampler's keys; a scene file's wide
// rotations are counted before they are split; numbers are range-checked as the floats they
// become. Each refusal comes within a second, with the limit in the message.
#include <chrono>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "io/gltf/loader.h"
#include "tests/support/gltf_files.h"
#include "tests/support/gltf_import.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;
using rt::test::append;
using rt::test::write_gltf;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A triangle with UVs whose materials (one per image) use images 0..n-1 as base colour; every
// image is `png` from a buffer view of its own or all of them from view 1.
std::string textured(const std::string& name, int images, bool one_view) {
  std::string buffer;
  append<float>(buffer, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1});
  const std::string png = rt::test::read_file(rt::test::source_path("tests/data/images/rgb8.png"));
  Json views = {{{"buffer", 0}, {"byteLength", 60}}};
  for (int i = 0; i < (one_view ? 1 : images); ++i) {
    views.push_back({{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", png.size()}});
    buffer += png;
  }
  Json doc = {{"scenes", {{{"nodes", {0}}}}},
              {"nodes", {{{"mesh", 0}}}},
              {"bufferViews", views},
              {"accessors",
               {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                {{"bufferView", 0}, {"byteOffset", 36}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}}};
  for (int i = 0; i < images; ++i) {
    doc["images"].push_back({{"bufferView", one_view ? 1 : 1 + i}, {"mimeType", "image/png"}});
    doc["textures"].push_back({{"source", i}});
    doc["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
    doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"material", i}});
  }
  return write_gltf(name, buffer, doc);
}

}  // namespace

TEST_CASE("budgets: glTF images on one buffer view are decoded once", "[io][gltf][limits]") {
  rt::test::ImportProblems error;
  const auto model = import_gltf(textured("six-images-one-view.gltf", 6, true), std::nullopt, LoadLimits{}, error);
  INFO(error.message);
  REQUIRE(model);
  CHECK(model->textures.size() == 1);
  for (const Material& m : model->materials) CHECK(m.texture.texture == 0);
}

TEST_CASE("budgets: a glTF file's images are summed from their headers before any is decoded", "[io][gltf][limits]") {
  LoadLimits limits;
  limits.scene_texels = 85 * 23;  // 23 of the 24 8 x 8 images (85 texels with mip levels each)
  LimitUsage usage;
  rt::test::ImportProblems error;
  const auto start = std::chrono::steady_clock::now();
  CHECK_FALSE(import_gltf(textured("24-images.gltf", 24, false), std::nullopt, limits, usage, error));
  CHECK(seconds_since(start) < 1.0);
  CHECK(error.over_limit);
  CHECK_THAT(error.message, Catch::Contains("its textures' 24 images need 2040 texels with their mip levels (read from "
                                            "their headers), more than the 1955 left of the scene's texture budget"));
  CHECK(usage.texels == 0);  // nothing was decoded
  limits.scene_texels = 85 * 24;
  REQUIRE(import_gltf(textured("24-images.gltf", 24, false), std::nullopt, limits, usage, error));
  CHECK(usage.texels == 85 * 24);
}

TEST_CASE("budgets: many primitives sharing one huge accessor stop before reading it", "[io][gltf][limits]") {
  // 12 primitives on one accessor of 2^25 zero vertices (valid glTF: no bufferView means zeros).
  Json doc = {{"scenes", {{{"nodes", {0}}}}},
              {"nodes", {{{"mesh", 0}}}},
              {"accessors", {{{"componentType", 5126}, {"count", 1 << 25}, {"type", "VEC3"}}}}};
  for (int i = 0; i < 12; ++i) doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}});
  doc["asset"] = {{"version", "2.0"}};
  const std::string path = rt::test::write_file("twelve-primitives.gltf", doc.dump());
  LimitUsage usage;
  rt::test::ImportProblems error;
  const auto start = std::chrono::steady_clock::now();
  CHECK_FALSE(import_gltf(path, std::nullopt, LoadLimits{}, usage, error));
  CHECK(seconds_since(start) < 1.0);
  CHECK(error.over_limit);
  CHECK_THAT(error.message,
             Catch::Contains("expected at most 33554432 vertices in a scene's meshes, found 402653184 in "
                             "this file's (counted from their accessors, before reading them)"));
  CHECK(usage.vertices == 0);
  // Meshes the default scene does not place are not counted.
  doc["nodes"][0].erase("mesh");
  CHECK(import_gltf(rt::test::write_file("unplaced-primitives.gltf", doc.dump()), std::nullopt, LoadLimits{}, usage,
                    error));
}

TEST_CASE("budgets: glTF channels share their sampler's keys, counted once", "[io][gltf][limits][animation]") {
  std::string buffer;
  append<float>(buffer, {0, 1, 2, 3});                          // times
  append<float>(buffer, {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0});  // translations
  Json doc = {
      {"scenes", {{{"nodes", Json::array()}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "SCALAR"}, {"min", {0}}, {"max", {3}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 16}}, {{"buffer", 0}, {"byteOffset", 16}, {"byteLength", 48}}}},
      {"animations", {{{"samplers", {{{"input", 0}, {"output", 1}}}}}}}};
  for (int i = 0; i < 300; ++i) {
    doc["nodes"].push_back({{"name", "n" + std::to_string(i)}});
    doc["scenes"][0]["nodes"].push_back(i);
    doc["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"node", i}, {"path", "translation"}}}});
  }
  const std::string path = write_gltf("shared-sampler.gltf", buffer, doc);
  LimitUsage usage;
  rt::test::ImportProblems error;
  const auto model = import_gltf(path, std::nullopt, LoadLimits{}, usage, error);
  INFO(error.message);
  REQUIRE(model);
  REQUIRE(model->tracks.size() == 300);
  CHECK(model->tracks.front().keys == model->tracks.back().keys);  // one copy of the keys
  CHECK(usage.animation_keys == 4);
  LoadLimits limits;
  limits.animation_keys = 3;
  CHECK_FALSE(import_gltf(path, std::nullopt, limits, usage = {}, error));
  CHECK(error.over_limit);
  CHECK_THAT(error.message, Catch::Contains("expected at most 3 animation keys in a scene, found 4 in this sampler"));
}

TEST_CASE("budgets: a scene file's wide rotations are counted before they are split", "[io][animation][limits]") {
  // 2001 keys alternating 0 and 5,898,240 degrees: 65,536 steps of 90 degrees between each pair.
  Json keys = Json::array();
  for (int i = 0; i < 2001; ++i)
    keys.push_back({{"frame", i}, {"value", {{"axis", {0, 1, 0}}, {"degrees", i % 2 ? 5898240 : 0}}}});
  Json scene = {{"camera", {{"position", {0, 0, 5}}, {"look_at", {0, 0, 0}}}},
                {"materials", {{"m", Json::object()}}},
                {"nodes", {{{"name", "spin"}, {"shape", "sphere"}, {"material", "m"}}}},
                {"animation", {{"tracks", {{{"node", "spin"}, {"property", "rotate"}, {"keys", keys}}}}}}};
  Diagnostics diags;
  const auto start = std::chrono::steady_clock::now();
  CHECK_FALSE(load_scene(rt::test::write_file("spin.json", scene.dump()), rt::test::load_options(), diags));
  CHECK(seconds_since(start) < 1.0);
  REQUIRE(diags.error_count() == 1);
  CHECK(diags.all()[0].pointer == "/animation/tracks/0/keys");
  CHECK_THAT(diags.all()[0].message,
             Catch::Contains("expected at most 1048576 animation keys in a scene, counting the steps of at most 90 "
                             "degrees that wide rotations are split into, found 131072001 in this track"));
  // 0 to 360 degrees in one step becomes four steps of 90: five keys.
  scene["animation"]["tracks"][0]["keys"] = {{{"frame", 0}, {"value", {{"axis", {0, 1, 0}}, {"degrees", 0}}}},
                                             {{"frame", 30}, {"value", {{"axis", {0, 1, 0}}, {"degrees", 360}}}}};
  const LoadedScene loaded = rt::test::load_scene_text("spin-once.json", scene.dump());
  REQUIRE(loaded.graph.tracks.size() == 1);
  CHECK(loaded.graph.tracks[0].keys->times.size() == 5);
}

TEST_CASE("budgets: numbers are range-checked as the floats they are stored in", "[io][errors][limits]") {
  Diagnostics diags;
  const std::string scene = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "nodes": [],
    "animation": {"fps": 1e-300}})";
  CHECK_FALSE(load_scene(rt::test::write_file("tiny-fps.json", scene), rt::test::load_options(), diags));
  REQUIRE(diags.error_count() == 1);
  CHECK(diags.all()[0].pointer == "/animation/fps");
  CHECK_THAT(diags.all()[0].message, Catch::Contains("expected a number in (0, 1000] in single precision, where it is "
                                                     "stored (this one becomes 0), found the number 1e-300"));
}
