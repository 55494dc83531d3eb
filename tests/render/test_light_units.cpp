// One light unit: every kind of light gives a diffuse surface the same direct light under Whitted
// and under the path tracer (core/lights/rect_light.h, docs/rendering.md "Lights and units").
// A grey plane seen from above, one light, no ambient, a black background, one bounce: what the
// camera sees is the light's direct illumination alone, averaged over the image.
#include <string>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "tests/support/loading.h"

using namespace rt;

namespace {

double mean_luminance(const LoadedScene& s, const std::string& integrator) {
  RenderSettings settings = s.settings;
  settings.integrator = integrator;
  Image image;
  render(s.scene, settings, image);
  double sum = 0.0;
  for (const Vec3& p : image.pixels) sum += (p.x + p.y + p.z) / 3.0;
  return sum / static_cast<double>(image.pixels.size());
}

LoadedScene plane_lit_by(const std::string& name, const std::string& light, const std::string& nodes = "") {
  return test::load_scene_text(name, R"({
  "render": { "width": 24, "height": 24, "max_depth": 1, "seed": 5, "samples_per_pixel": 256,
              "shadow_samples": 256, "antialias": { "mode": "none" } },
  "camera": { "position": [0, 6, 0.01], "look_at": [0, 0, 0], "fov": 50 },
  "background": [0, 0, 0],
  "ambient": [0, 0, 0],
  "materials": { "grey": { "kd": 0.6, "ks": 0 }, "glow": { "kd": 0, "ks": 0, "emission": [3, 2.5, 2] } },
  "lights": [ )" + light + R"( ],
  "nodes": [ { "shape": "plane", "material": "grey", "transform": { "scale": 10 } } )" +
                                         nodes + R"( ]
})");
}

// `tolerance`: 0.5 % for the scene's lights, which agree within 0.1 %; emissive surfaces are drawn
// from a table by both, noisier (seeds move Whitted's mean by 0.8 %), and get 2 %.
void check_same_light(const std::string& name, const std::string& light, const std::string& nodes = "",
                      double tolerance = 0.005) {
  LoadedScene s = plane_lit_by(name, light, nodes);
  if (!nodes.empty()) {
    s.settings.shadow_samples = 1024;
    s.settings.path.samples_per_pixel = 1024;
  }
  const double whitted = mean_luminance(s, "whitted"), path = mean_luminance(s, "path");
  INFO(name << ": Whitted " << whitted << ", path tracer " << path);
  CHECK(whitted > 0.01);
  CHECK(path == Approx(whitted).epsilon(tolerance));
}

}  // namespace

TEST_CASE("light units: a point light lights a diffuse plane alike in both integrators", "[lights][units]") {
  check_same_light("lu_point.json", R"({ "type": "point", "position": [0.5, 2, 0.3], "color": [1, 0.8, 0.6],
    "intensity": 3, "attenuation": [1, 0, 0.2] })");
}

TEST_CASE("light units: a spot light lights a diffuse plane alike in both integrators", "[lights][units]") {
  check_same_light("lu_spot.json", R"({ "type": "spot", "position": [0, 3, 0], "direction": [0.2, -1, 0],
    "inner_angle": 15, "outer_angle": 35, "color": 2 })");
}

TEST_CASE("light units: a directional light lights a diffuse plane alike in both integrators", "[lights][units]") {
  check_same_light("lu_sun.json", R"({ "type": "directional", "direction": [0.3, -1, 0.2], "color": 0.8 })");
}

TEST_CASE("light units: a rect light lights a diffuse plane alike in both integrators", "[lights][units]") {
  SECTION("without attenuation (a Whitted scene's default)") {
    check_same_light("lu_rect.json", R"({ "type": "rect", "corner": [-1, 2, -0.5], "edge1": [2, 0, 0],
      "edge2": [0, 0, 1], "color": [1, 0.9, 0.8] })");
  }
  SECTION("falling off with distance, tilted") {
    check_same_light("lu_rect_falloff.json", R"({ "type": "rect", "corner": [-0.5, 1.5, -1], "edge1": [1, 0.5, 0],
      "edge2": [0, 0, 2], "color": 4, "attenuation": [0.5, 0.3, 0.4] })");
  }
  SECTION("two-sided, out of view, lighting the plane with its back") {
    check_same_light("lu_rect_back.json", R"({ "type": "rect", "corner": [3.5, 0.5, -1], "edge1": [0, 1, 0],
      "edge2": [0, 0, 2], "color": 6, "two_sided": true })");
  }
  SECTION("as an ordinary emitter of radiance colour: \"radiance\": true") {
    const LoadedScene s = plane_lit_by("lu_rect_radiance.json", R"({ "type": "rect", "corner": [-0.5, 2, -0.5],
      "edge1": [1, 0, 0], "edge2": [0, 0, 2], "color": 5, "radiance": true })");
    const RectLight& rect = std::get<RectLight>(s.scene.lights[0]);
    CHECK(rect.attenuation.c2 == Approx(kPi / 2.0f));
    CHECK(rect.lighting_radiance(0.7f, 2.0f).x == Approx(5.0f));
    check_same_light("lu_rect_emitter.json", R"({ "type": "rect", "corner": [-0.5, 2, -0.5], "edge1": [1, 0, 0],
      "edge2": [0, 0, 1], "color": 5, "radiance": true })");
  }
}

TEST_CASE("light units: an emissive sphere and a mesh light a diffuse plane alike in both integrators",
          "[lights][units]") {
  // Out of view (so the camera does not see the glow itself), lighting the plane from the side.
  check_same_light(
      "lu_glow.json", "",
      R"(, { "shape": "sphere", "material": "glow", "transform": { "translate": [3.6, 1, 0], "scale": 0.6 } })", 0.02);
  check_same_light("lu_glow_mesh.json", "",
                   R"(, { "mesh": { "file": ")" + test::source_path("../shared/gltf/Box/glTF/Box.gltf") +
                       R"(" }, "material": "glow", "transform": { "translate": [-3.8, 0.8, 0.5] } })",
                   0.02);
}
