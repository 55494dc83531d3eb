// Pixel samplers: what anti-aliasing does to an edge.
#include <string>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "io/scene_loader.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;

TEST_CASE("anti-aliased coverage of a half-plane edge converges to the covered fraction", "[render][antialias]") {
  // A white half-plane (ambient 1, kd 1) on black, its edge at pixel x = 10.3 of a 20 x 20 image
  // (fov 90 at distance 5: world x = px / 2 - 5), so pixel 10 is 30 % covered.
  const auto pixel_value = [](const std::string& antialias) {
    const std::string json = R"({
      "render": { "width": 20, "height": 20, "antialias": )" +
                             antialias + R"( },
      "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 90 },
      "ambient": 1, "materials": { "white": { "kd": 1 } },
      "nodes": [ { "shape": "plane", "material": "white",
                   "transform": { "translate": [-24.925, 0, -5], "rotate": [90, 0, 0], "scale": [25.075, 1, 50] } } ] })";
    const LoadedScene s = rt::test::load_scene_text("half_plane.json", json);
    Image image;
    render(s.scene, s.settings, image);
    CHECK(image.at(5, 10).x == 1.0f);   // covered
    CHECK(image.at(15, 10).x == 0.0f);  // not
    return image.at(10, 10).x;
  };
  CHECK(pixel_value(R"({ "mode": "none" })") == 0.0f);  // the centre (10.5) is not covered
  const float regular4 = pixel_value(R"({ "mode": "uniform", "samples": 4 })");
  const float regular16 = pixel_value(R"({ "mode": "uniform", "samples": 16 })");
  const float jittered16 = pixel_value(R"({ "mode": "uniform", "samples": 16, "jitter": true })");
  CHECK(regular4 == Approx(0.25f));       // one column of cell centres out of four
  CHECK(regular16 == Approx(5.0f / 16));  // five of sixteen: 0.3125
  CHECK(jittered16 == Approx(0.3f).margin(0.02));
}
