// Every light type is reachable from a JSON scene: point, rect, spot and directional.
#include <catch2/catch.hpp>

#include "tests/support/loading.h"

using namespace rt;

TEST_CASE("JSON scenes: spot and directional lights as the schema describes them", "[io][lights]") {
  const LoadedScene loaded = rt::test::load_scene_text("json-lights.json", R"({
    "camera": {"position": [0, 2, 6], "look_at": [0, 0, 0]},
    "materials": {"grey": {"kd": 0.5}},
    "lights": [
      {"type": "spot", "position": [0, 4, 0], "direction": [0, -2, 0], "inner_angle": 10, "outer_angle": 25,
       "color": [1, 0.5, 0.25], "intensity": 2},
      {"type": "spot", "position": [1, 4, 0], "direction": [0, -1, 0]},
      {"type": "directional", "direction": [1, -1, 0], "color": [0.5, 0.5, 0.5]}
    ],
    "nodes": [{"shape": "plane", "material": "grey"}]})");
  const std::vector<Light>& lights = loaded.scene.lights;
  REQUIRE(lights.size() == 3);
  const auto* spot = std::get_if<SpotLight>(&lights[0]);
  REQUIRE(spot);
  CHECK(spot->position == Vec3(0, 4, 0));
  CHECK(spot->direction == Vec3(0, -1, 0));  // normalised
  CHECK(spot->color == Vec3(2, 1, 0.5f));
  CHECK(spot->cos_inner == Approx(std::cos(radians(10.0f))));
  CHECK(spot->cos_outer == Approx(std::cos(radians(25.0f))));
  CHECK(spot->attenuation.c0 == 1.0f);  // no falloff unless asked, as a JSON point light
  CHECK(spot->attenuation.c2 == 0.0f);
  // Full inside the inner cone, nothing outside the outer, glTF's t^2 between.
  CHECK(spot->cone(Vec3(0, -1, 0)) == 1.0f);
  CHECK(spot->cone(glm::normalize(Vec3(std::tan(radians(30.0f)), -1, 0))) == 0.0f);
  const float c = std::cos(radians(17.5f));
  const float t = (c - spot->cos_outer) / (spot->cos_inner - spot->cos_outer);
  CHECK(spot->cone(Vec3(std::sin(radians(17.5f)), -c, 0)) == Approx(t * t).epsilon(1e-4));
  const auto* defaults = std::get_if<SpotLight>(&lights[1]);
  REQUIRE(defaults);
  CHECK(defaults->cos_inner == 1.0f);  // inner 0
  CHECK(defaults->cos_outer == Approx(std::cos(radians(30.0f))));
  const auto* sun = std::get_if<DirectionalLight>(&lights[2]);
  REQUIRE(sun);
  CHECK(sun->direction.x == Approx(std::sqrt(0.5f)));
  CHECK(sun->direction.y == Approx(-std::sqrt(0.5f)));
  CHECK(sun->color == Vec3(0.5f));
}
