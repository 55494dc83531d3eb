// Light selection by power (core/lights/light_selection.h): with many lights the path tracer
// draws one a bounce, in proportion to its power, and converges to the image that samples each.
#include <string>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "tests/support/loading.h"

using namespace rt;

TEST_CASE("light selection: probabilities follow power, a few lights are each sampled", "[lights][selection]") {
  CHECK_FALSE(LightSelection(std::vector<float>(8, 1.0f)).active());
  // Nine lights with power (and one without): active, each in proportion.
  std::vector<float> powers = {1, 2, 3, 0, 4, 5, 6, 7, 8, 9};
  const LightSelection s(powers);
  REQUIRE(s.active());
  CHECK(s.probability(0) == Approx(1.0f / 45.0f));
  CHECK(s.probability(3) == 0.0f);
  CHECK(s.probability(9) == Approx(9.0f / 45.0f));
  float p = 0.0f;
  CHECK(s.sample(0.0f, p) == 0);
  CHECK(s.sample(0.999f, p) == 9);
  CHECK(p == Approx(9.0f / 45.0f));
  // Drawing by u in [0, 1) lands on each light as often as its probability says (never on light 3).
  std::vector<int> count(powers.size(), 0);
  constexpr int kDraws = 45000;
  for (int i = 0; i < kDraws; ++i) ++count[s.sample((static_cast<float>(i) + 0.5f) / kDraws, p)];
  for (size_t l = 0; l < powers.size(); ++l) CHECK(count[l] == Approx(kDraws * powers[l] / 45.0f).margin(2));
}

TEST_CASE("light selection: a room of 24 lamps converges to the image that samples every lamp", "[lights][selection]") {
  std::string lamps;
  for (int i = 0; i < 24; ++i) {
    const float x = static_cast<float>(i % 6) - 2.5f, z = static_cast<float>(i / 6) - 1.5f;
    const float power = 0.05f + 0.4f * static_cast<float>(i % 5);
    lamps += std::string(i ? ", " : "") + R"({ "type": "point", "position": [)" + std::to_string(x) + ", 1.5, " +
             std::to_string(z) + R"(], "color": )" + std::to_string(power) + R"(, "attenuation": [0, 0, 1] })";
  }
  lamps += R"(, { "type": "rect", "corner": [-1, 2, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 1], "color": 2,
    "radiance": true })";
  LoadedScene s = test::load_scene_text("ls_lamps.json", R"({
  "render": { "width": 24, "height": 24, "max_depth": 2, "seed": 3, "samples_per_pixel": 256, "integrator": "path" },
  "camera": { "position": [0, 6, 0.01], "look_at": [0, 0, 0], "fov": 60 },
  "background": [0, 0, 0],
  "materials": { "grey": { "kd": 0.6, "ks": 0 }, "box": { "kd": [0.3, 0.5, 0.7] } },
  "lights": [ )" + lamps + R"( ],
  "nodes": [ { "shape": "plane", "material": "grey", "transform": { "scale": 10 } },
             { "shape": "cube", "material": "box", "transform": { "translate": [0.5, 0.4, 0], "scale": 0.4 } } ]
})");
  REQUIRE(s.scene.light_selection.active());
  const auto mean = [&](const Scene& scene, RenderStats& stats) {
    Image image;
    stats = render(scene, s.settings, image);
    double sum = 0.0;
    for (const Vec3& p : image.pixels) sum += (p.x + p.y + p.z) / 3.0;
    return sum / static_cast<double>(image.pixels.size());
  };
  RenderStats drawn_stats, every_stats;
  const double drawn = mean(s.scene, drawn_stats);
  Scene every = s.scene;
  every.light_selection = LightSelection{};
  const double each = mean(every, every_stats);
  INFO("one lamp drawn by power: " << drawn << ", every lamp: " << each);
  CHECK(drawn == Approx(each).epsilon(0.01));
  // One shadow ray a bounce instead of 25.
  CHECK(drawn_stats.rays[RayKind::kShadow] * 10 < every_stats.rays[RayKind::kShadow]);
}
