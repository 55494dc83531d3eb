// Thin-lens camera: rays through any point of the lens meet on the plane of focus; aperture 0 is
// the pinhole image bit for bit; things off the plane of focus blur.
#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "core/sampling.h"
#include "io/json/document.h"
#include "io/scene_loader.h"
#include "tests/support/geometry.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;

TEST_CASE("thin lens: every lens ray of a pixel passes through one point of the focal plane", "[camera][dof]") {
  Camera c = Camera::look_at({0, 1, 5}, {0, 0, 0}, {0, 1, 0}, 50.0f);
  c.aperture = 0.3f;
  c.focus_distance = 4.0f;
  const Ray pinhole = c.generate_ray(30.5f, 12.5f, 64, 48);
  const Vec3 focus = pinhole.at(4.0f / glm::dot(pinhole.direction, c.forward));
  const SampleStream stream(1, 0, 2, 3);
  float spread = 0.0f;
  for (uint64_t i = 0; i < 200; ++i) {
    const Ray r = c.generate_ray(30.5f, 12.5f, 64, 48, stream.get2(SamplePurpose::kLens, 0, i));
    // The origin is on the lens disk, within the aperture, in the plane through the camera.
    const Vec3 offset = r.origin - c.position;
    CHECK(glm::length(offset) <= 0.3f + 1e-5f);
    CHECK(std::fabs(glm::dot(offset, c.forward)) < 1e-5f);
    spread = std::max(spread, glm::length(offset));
    // It reaches the same focal point.
    const float t = glm::dot(focus - r.origin, r.direction);
    rt::test::check_vec(r.at(t), focus, 1e-4);
  }
  CHECK(spread > 0.2f);  // the lens is used, not just its centre
  c.aperture = 0.0f;
  const Ray same = c.generate_ray(30.5f, 12.5f, 64, 48, Vec2(0.9f, 0.1f));
  CHECK(same.origin == pinhole.origin);
  CHECK(same.direction == pinhole.direction);
}

TEST_CASE("aperture 0 is the pinhole image bit for bit, an aperture blurs what is out of focus", "[camera][dof]") {
  Diagnostics diags;
  const auto scene = load_scene(rt::test::source_path("scenes/depth_of_field.json"), rt::test::load_options(), diags);
  REQUIRE(scene);
  RenderSettings settings = scene->settings;
  settings.width = 96;
  settings.height = 54;
  Image lens, pinhole, closed;
  render(scene->scene, settings, lens);
  Scene pin = scene->scene;
  pin.camera.aperture = 0.0f;
  render(pin, settings, closed);
  // The same scene loaded without the lens keys.
  Json json = Json::parse(rt::test::read_file(rt::test::source_path("scenes/depth_of_field.json")));
  json["camera"].erase("aperture");
  json["camera"].erase("focus_distance");
  const std::string text = json.dump();
  const LoadedScene plain = rt::test::load_scene_text("dof_pinhole.json", text);
  render(plain.scene, settings, pinhole);
  CHECK(closed.pixels == pinhole.pixels);
  CHECK(lens.pixels != pinhole.pixels);
  // Near the in-focus ball's centre the two agree; on the near (blurred) ball's edge they do not.
  float focus_diff = 0.0f, blur_diff = 0.0f;
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      const float d = glm::length(lens.at(x, y) - pinhole.at(x, y));
      if (x > 46 && x < 58 && y > 22 && y < 30) focus_diff = std::max(focus_diff, d);
      blur_diff = std::max(blur_diff, d);
    }
  CHECK(focus_diff < 0.1f);
  CHECK(blur_diff > 0.3f);
}
