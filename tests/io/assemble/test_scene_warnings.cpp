// Scenes that render, but not as meant: nothing to render, nothing lighting it, a light that
// reaches nothing, a camera inside a shape. Warnings, the same from render's loader and validate.
#include <catch2/catch.hpp>

#include "io/assemble/scene_warnings.h"
#include "io/scene_loader.h"
#include "io/scene_validator.h"
#include "tests/support/loading.h"

using namespace rt;

namespace {

// A lit sphere on a floor, with `lights`, `ambient` and `nodes` replaceable.
std::string scene(const std::string& lights, const std::string& nodes, const std::string& extra = "") {
  return R"({
  "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], "fov": 45},
  "materials": {"grey": {"kd": 0.6}},
)" + extra +
         R"(
  "lights": )" +
         lights + R"(,
  "nodes": )" +
         nodes + "\n}\n";
}

const char* kNodes = R"([{"name": "floor", "shape": "plane", "material": "grey", "transform": {"scale": 5}},
            {"name": "ball", "shape": "sphere", "material": "grey", "transform": {"translate": [0, 1, 0]}}])";

// The warnings of both commands, which must agree; each "pointer: message".
std::vector<std::string> warnings(const std::string& name, const std::string& text) {
  const std::string path = rt::test::write_file(name, text);
  Diagnostics loaded;
  CHECK(load_scene(path, rt::test::load_options(), loaded));
  const Diagnostics validated = validate_file(path, rt::test::load_options());
  std::vector<std::string> out, again;
  for (const Diagnostic& d : loaded.all()) out.push_back(d.pointer + ": " + d.message);
  for (const Diagnostic& d : validated.all()) again.push_back(d.pointer + ": " + d.message);
  CHECK(out == again);
  return out;
}

}  // namespace

TEST_CASE("scene warnings: a well-made scene gets none", "[io][warnings]") {
  CHECK(warnings("warn_none.json", scene(R"([{"type": "rect", "corner": [-1, 4, -1], "edge1": [2, 0, 0],
                                                "edge2": [0, 0, 2]}])",
                                         kNodes))
            .empty());
}

TEST_CASE("scene warnings: a rect light facing away from everything", "[io][warnings]") {
  // edge1 x edge2 = z × x = +y: up, at the sky (x × z would face down, onto the scene).
  const auto w = warnings("warn_rect.json", scene(R"([{"type": "point", "position": [3, 3, 3]},
     {"type": "rect", "corner": [-1, 4, -1], "edge1": [0, 0, 2], "edge2": [2, 0, 0]}])",
                                                  kNodes));
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::StartsWith("/lights/1: this rect light reaches no geometry") &&
                       Catch::Contains("swap edge1 and edge2"));
  // Two-sided, it lights the scene.
  CHECK(warnings("warn_rect2.json", scene(R"([{"type": "rect", "corner": [-1, 4, -1], "edge1": [0, 0, 2],
                                              "edge2": [2, 0, 0], "two_sided": true}])",
                                          kNodes))
            .empty());
}

TEST_CASE("scene warnings: no light and no ambient, an empty scene", "[io][warnings]") {
  auto w = warnings("warn_dark.json", scene("[]", kNodes));
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::StartsWith(": the scene has no light, no ambient and no emissive material"));
  CHECK(warnings("warn_ambient.json", scene("[]", kNodes, R"("ambient": [0.2, 0.2, 0.2],)")).empty());
  w = warnings("warn_empty.json", scene(R"([{"type": "point", "position": [3, 3, 3]}])", "[]"));
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::StartsWith("/nodes: the scene places nothing to render"));
}

TEST_CASE("scene warnings: the camera inside a closed shape", "[io][warnings]") {
  const auto w = warnings("warn_inside.json", scene(R"([{"type": "point", "position": [3, 3, 3]}])",
                                                    R"([{"name": "dome", "shape": "sphere", "material": "grey",
                                                         "transform": {"scale": 20}}])"));
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::StartsWith("/nodes/0: the camera starts inside this closed shape"));
}

TEST_CASE("scene warnings: the geometry of the tests", "[io][warnings]") {
  const Aabb box{Vec3(-1.0f), Vec3(1.0f)};
  SpotLight spot;
  spot.position = Vec3(0.0f, 5.0f, 0.0f);
  spot.direction = Vec3(0.0f, -1.0f, 0.0f);
  spot.cos_outer = std::cos(glm::radians(10.0f));
  CHECK(light_can_reach(Light(spot), box));
  spot.direction = Vec3(0.0f, 1.0f, 0.0f);  // at the sky
  CHECK_FALSE(light_can_reach(Light(spot), box));
  spot.direction = glm::normalize(Vec3(0.3f, -1.0f, 0.0f));  // 16.7 degrees off, the box spans 11.3 + 10 cone
  CHECK(light_can_reach(Light(spot), box));
  spot.direction = glm::normalize(Vec3(1.0f, -1.0f, 0.0f));  // 45 degrees off
  CHECK_FALSE(light_can_reach(Light(spot), box));

  const Mat4 up = compose_trs(Vec3(0.0f), Vec3(-90.0f, 0.0f, 0.0f), Vec3(1.0f, 1.0f, 2.0f));  // +Z to +Y, 2 tall
  CHECK(inside_shape(ShapeKind::kCylinder, up, Vec3(0.0f, 1.9f, 0.0f)));
  CHECK_FALSE(inside_shape(ShapeKind::kCylinder, up, Vec3(0.0f, 2.1f, 0.0f)));
  CHECK(inside_shape(ShapeKind::kCone, up, Vec3(0.0f, 1.8f, 0.8f)));  // radius 0.9 at height 1.8
  CHECK_FALSE(inside_shape(ShapeKind::kCone, up, Vec3(0.0f, 1.0f, 0.8f)));
  CHECK(inside_shape(ShapeKind::kCube, Mat4(1.0f), Vec3(0.99f, -0.99f, 0.0f)));
  CHECK_FALSE(inside_shape(ShapeKind::kPlane, Mat4(1.0f), Vec3(0.0f)));
}
