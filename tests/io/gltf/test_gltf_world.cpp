// What Blender's scene carries beyond glTF, as tools/blender/rtcli/export.py writes it: the world
// (scene extras rtcli_world: a colour, or an environment image beside the file) and an area
// light hidden from the camera (rtcli_area_light.camera = false, Cycles' default for lights).
#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

#include "tests/support/gltf_files.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

// A square at z = 0, a camera 4 m in front of it, the scene's extras `world`, and optionally an
// area light between them facing the camera.
std::string write_model(const std::string& folder, const Json& world, const Json& area_light = nullptr) {
  std::filesystem::create_directories(rt::test::output_path(folder));
  Json doc = {{"scenes", {{{"nodes", {0, 1}}}}},
              {"nodes", {{{"mesh", 0}}, {{"name", "eye"}, {"translation", {0.5, 0.5, 4}}, {"camera", 0}}}},
              {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}}},
              {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", 6}}}}}}},
              {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}}},
              {"bufferViews", {{{"buffer", 0}, {"byteLength", 48}}}}};
  if (!world.is_null()) doc["scenes"][0]["extras"] = {{"rtcli_world", world}};
  if (!area_light.is_null()) {
    // At (0.5, 0.5, 2), turned to face +Z (towards the camera): a half turn about X.
    doc["nodes"].push_back({{"name", "softbox"},
                            {"translation", {0.5, 0.5, 2}},
                            {"rotation", {1, 0, 0, 0}},
                            {"extras", {{"rtcli_area_light", area_light}}}});
    doc["scenes"][0]["nodes"].push_back(2);
  }
  return rt::test::write_gltf(folder + "/model.gltf", rt::test::square_positions(), doc);
}

// A flat Radiance image of 4 x 2 pixels, all (1, 0.5, 0.25).
void write_hdr(const std::string& path) {
  std::ofstream f(path, std::ios::binary);
  f << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
  for (int i = 0; i < 8; ++i) f << '\x80' << '\x40' << '\x20' << '\x81';
}

std::optional<LoadedScene> load(const std::string& path, Diagnostics& diags, LoadOptions options = {}) {
  LoadOptions o = rt::test::load_options();
  o.background = options.background;
  o.environment = options.environment;
  return load_scene(path, o, diags);
}

}  // namespace

TEST_CASE("glTF world: a model on its own shows its scene's rtcli_world colour, times its strength", "[gltf][world]") {
  Diagnostics diags;
  const auto loaded = load(write_model("world-color", {{"color", {0.2, 0.3, 0.5}}, {"strength", 2.0}}), diags);
  REQUIRE(loaded);
  CHECK(diags.all().empty());
  const Vec3 seen = loaded->scene.background.radiance(Vec3(0, 0, -1));
  CHECK(seen.x == Approx(0.4f));
  CHECK(seen.y == Approx(0.6f));
  CHECK(seen.z == Approx(1.0f));
  // --background still replaces it.
  LoadOptions replaced;
  replaced.background = std::array<float, 3>{0.1f, 0.1f, 0.1f};
  const auto overridden = load(write_model("world-color", {{"color", {0.2, 0.3, 0.5}}}), diags, replaced);
  REQUIRE(overridden);
  CHECK(overridden->scene.background.radiance(Vec3(0, 0, -1)).z == Approx(0.1f));
}

TEST_CASE("glTF world: an environment image beside the file, with its strength", "[gltf][world]") {
  const std::string model = write_model("world-image", {{"image", "sky.hdr"}, {"strength", 3.0}, {"rotation", 90}});
  write_hdr(rt::test::output_path("world-image/sky.hdr"));
  Diagnostics diags;
  const auto loaded = load(model, diags);
  for (const Diagnostic& d : diags.all()) UNSCOPED_INFO(format_diagnostic(d));
  REQUIRE(loaded);
  REQUIRE(loaded->scene.background.is_image());
  const Vec3 seen = loaded->scene.background.radiance(Vec3(0.3f, 0.8f, -0.5f));
  CHECK(seen.x == Approx(3.0f).epsilon(0.02));
  CHECK(seen.y == Approx(1.5f).epsilon(0.02));
  CHECK(seen.z == Approx(0.75f).epsilon(0.02));
  CHECK(std::find(loaded->inputs.begin(), loaded->inputs.end(), rt::test::output_path("world-image/sky.hdr")) !=
        loaded->inputs.end());
}

TEST_CASE("glTF world: an image outside the model's folder, a broken image and bad values are reported",
          "[gltf][world]") {
  Diagnostics outside;
  CHECK_FALSE(load(write_model("world-outside", {{"image", "../world-image/sky.hdr"}}), outside));
  REQUIRE(outside.all().size() == 1);
  CHECK(outside.all()[0].pointer == "/scenes/0/extras/rtcli_world/image");
  CHECK_THAT(outside.all()[0].message, Catch::Contains("outside"));

  const std::string broken = write_model("world-broken", {{"image", "sky.hdr"}});
  rt::test::write_file("world-broken/sky.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 99999 +X 99999\n");
  Diagnostics diags;
  CHECK_FALSE(load(broken, diags));
  REQUIRE_FALSE(diags.all().empty());
  CHECK_THAT(format_diagnostic(diags.all()[0]), Catch::Contains("sky.hdr") && Catch::Contains("rtcli_world"));

  for (const Json& bad : {Json{{"color", {0.2, -1, 0.5}}}, Json{{"color", {0.2, 0.3, 0.5}}, {"strength", -1}},
                          Json{{"image", ""}}, Json{{"image", "sky.hdr"}, {"rotation", 1000}}, Json("blue")}) {
    INFO(bad.dump());
    Diagnostics warned;
    const auto loaded = load(write_model("world-bad", bad), warned);
    REQUIRE(loaded);
    REQUIRE(warned.all().size() == 1);
    CHECK(warned.all()[0].severity == Severity::kWarning);
    CHECK(warned.all()[0].pointer == "/scenes/0/extras/rtcli_world");
    CHECK(loaded->scene.background.radiance(Vec3(0, 0, -1)).x == Approx(kModelBackground));
  }
}

TEST_CASE("glTF world: a scene file placing the model keeps its own background", "[gltf][world]") {
  write_model("world-placed", {{"color", {0.2, 0.3, 0.5}}});
  const LoadedScene loaded =
      rt::test::load_scene_text("world-placed/scene.json",
                                R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "background": [0, 0, 0],
          "nodes": [{"mesh": {"file": "model.gltf"}}]})");
  CHECK(loaded.scene.background.radiance(Vec3(0, 0, -1)).z == Approx(0.0f));
}

TEST_CASE("glTF area light: camera = false hides its face from camera rays only", "[gltf][world][lights]") {
  for (const bool visible : {true, false}) {
    Diagnostics diags;
    const auto loaded =
        load(write_model("area-camera", nullptr, {{"size", {1, 1}}, {"power", 100}, {"camera", visible}}), diags);
    REQUIRE(loaded);
    const Scene& scene = loaded->scene;
    Ray ray;
    ray.origin = Vec3(0.5f, 0.5f, 4.0f);
    ray.direction = Vec3(0.0f, 0.0f, -1.0f);
    // A reflection or bounce meets the light's face either way...
    Ray bounce = ray;
    SceneHit met;
    CHECK(scene.intersect(bounce, met));
    CHECK(met.light != nullptr);
    // ...a camera ray only when the light is visible to the camera; else it meets the square behind.
    Ray camera = ray;
    SceneHit seen;
    scene.intersect_packet(&camera, &seen, 1);
    CHECK((seen.light != nullptr) == visible);
    CHECK(seen.surface == !visible);
  }
}
