// Whitted's direct light at a point without kd (glass, a mirror): Phong's factor is its highlight
// alone, next to 0 outside a narrow cone about the mirror direction, and a light sample that adds
// less than 2^-14 of the sample's value there adds nothing: direct_lighting traces no shadow ray
// for it (kFaintLight, core/render/direct_lighting.cpp). With kd every sample in front of the
// surface is traced, as before.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "core/render/direct_lighting.h"
#include "core/render/integrator.h"
#include "tests/support/loading.h"

using namespace rt;

namespace {

// One light over an empty space (the only shape far below, out of every shadow ray's way).
LoadedScene scene_with(const std::string& light) {
  return rt::test::load_scene_text("highlight_shadows.json", R"({
    "render": {"width": 8, "height": 8, "shadow_samples": 16},
    "camera": {"position": [0, 2, 9], "look_at": [0, 0, 0]},
    "materials": {"matte": {"kd": 0.5}},
    "lights": [)" + light + R"(],
    "nodes": [{"shape": "sphere", "material": "matte", "transform": {"translate": [0, -20, 0]}}]
  })");
}

// A point at the origin facing +y, seen from `wo`: a highlight of shininess 300 (kd 0 unless given).
EvaluatedSurface glossy_point(Vec3 wo, float kd = 0.0f) {
  EvaluatedSurface s;
  s.position = Vec3(0.0f);
  s.n = s.ng = Vec3(0.0f, 1.0f, 0.0f);
  s.wo = glm::normalize(wo);
  s.diffuse = Vec3(kd);
  s.specular = Vec3(0.5f);
  s.shininess = 300.0f;
  return s;
}

struct Lighting {
  Vec3 radiance;
  uint64_t shadow_rays;
};

// `weight`: the point's weight in its sample (1: a camera ray's hit).
Lighting light_at(const LoadedScene& s, const EvaluatedSurface& point, float weight = 1.0f) {
  RayCounters counters;
  TraceContext ctx{s.scene, s.settings, counters, SampleStream(1, 0, 7, 0)};
  const Vec3 radiance = direct_lighting(point, 0, weight, ctx, nullptr);
  return {radiance, counters[RayKind::kShadow]};
}

// The light at (0, 5, 5) reflects about +y into (0, 1, -1): the highlight's direction.
const Vec3 kMirror(0.0f, 1.0f, -1.0f);
const Vec3 kAside(1.0f, 1.0f, 0.0f);  // 60 degrees from it: cos^300 is far below the smallest float

// Towards the viewer `degrees` from the mirror direction, nearer the normal (in the y-z plane).
Vec3 off_mirror(float degrees) {
  const float a = (45.0f - degrees) * kPi / 180.0f;
  return Vec3(0.0f, std::cos(a), -std::sin(a));
}

}  // namespace

TEST_CASE("highlight shadows: a point light outside a kd-less point's highlight gets no shadow ray",
          "[lights][shadow]") {
  const LoadedScene s = scene_with(R"({"type": "point", "position": [0, 5, 5], "intensity": 1})");
  const Lighting aside = light_at(s, glossy_point(kAside));
  CHECK(aside.shadow_rays == 0);
  CHECK(aside.radiance == Vec3(0.0f));
  const Lighting in_highlight = light_at(s, glossy_point(kMirror));
  CHECK(in_highlight.shadow_rays == 1);
  CHECK(in_highlight.radiance.x > 0.0f);
  // With kd the light is traced wherever it is in front, highlight or not.
  const Lighting matte = light_at(s, glossy_point(kAside, 0.5f));
  CHECK(matte.shadow_rays == 1);
  CHECK(matte.radiance.x > 0.0f);
}

TEST_CASE("highlight shadows: a light that adds below 2^-14 of the sample at a kd-less point gets no shadow ray",
          "[lights][shadow]") {
  const LoadedScene s = scene_with(R"({"type": "point", "position": [0, 5, 5], "intensity": 1})");
  // 20 degrees off: 0.5 cos^300 is 3.9e-9, a float above 0, but far below 2^-14 (6.1e-5).
  const float far = 0.5f * std::pow(std::cos(20.0f * kPi / 180.0f), 300.0f);
  REQUIRE(far > 0.0f);
  REQUIRE(far < 0x1p-14f);
  const Lighting skirt = light_at(s, glossy_point(off_mirror(20.0f)));
  CHECK(skirt.shadow_rays == 0);
  CHECK(skirt.radiance == Vec3(0.0f));
  // 8 degrees off, 0.5 cos^300 is 0.027: traced for a camera ray's hit, not for a hit that
  // weighs 2^-10 in its sample (2.6e-5 of it).
  const Lighting near = light_at(s, glossy_point(off_mirror(8.0f)));
  CHECK(near.shadow_rays == 1);
  CHECK(near.radiance.x == Approx(0.5f * std::pow(std::cos(8.0f * kPi / 180.0f), 300.0f)).epsilon(1e-3));
  const Lighting deep = light_at(s, glossy_point(off_mirror(8.0f)), 0x1p-10f);
  CHECK(deep.shadow_rays == 0);
  CHECK(deep.radiance == Vec3(0.0f));
  // With kd the light is traced at any weight.
  CHECK(light_at(s, glossy_point(off_mirror(20.0f), 0.5f), 0x1p-10f).shadow_rays == 1);
}

TEST_CASE("highlight shadows: a rect light's samples outside a kd-less point's highlight get no shadow rays",
          "[lights][shadow]") {
  // 1 x 1, facing down, centred on (0, 5, 5); sixteen samples.
  const LoadedScene s = scene_with(
      R"({"type": "rect", "corner": [-0.5, 5, 4.5], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "intensity": 1})");
  const Lighting aside = light_at(s, glossy_point(kAside));
  CHECK(aside.shadow_rays == 0);
  CHECK(aside.radiance == Vec3(0.0f));
  const Lighting in_highlight = light_at(s, glossy_point(kMirror));
  CHECK(in_highlight.shadow_rays == 16);
  CHECK(in_highlight.radiance.x > 0.0f);
  // Seen 11 degrees off the mirror direction, the light straddles the edge of the cone where a
  // sample (a sixteenth of the light) adds 2^-14: the samples inside it are traced, the others not.
  const Lighting edge = light_at(s, glossy_point(off_mirror(11.0f)));
  CHECK(edge.shadow_rays > 0);
  CHECK(edge.shadow_rays < 16);
  CHECK(edge.radiance.x > 0.0f);
  const Lighting matte = light_at(s, glossy_point(kAside, 0.5f));
  CHECK(matte.shadow_rays == 16);
}
