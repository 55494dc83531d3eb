// Rectangular area lights and soft shadows: emission and orientation, stratification, the
// shadow below an occluder's edge, the penumbra's width by similar triangles.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "core/render/direct_lighting.h"
#include "core/render/integrator.h"
#include "core/render/renderer.h"
#include "io/scene_loader.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

// Direct light at a white Lambertian floor point (x, 0, 0), normal +Y.
Vec3 floor_light(const Scene& scene, const RenderSettings& settings, float x) {
  EvaluatedSurface s;
  s.position = Vec3(x, 0.0f, 0.0f);
  s.n = s.ng = Vec3(0.0f, 1.0f, 0.0f);
  s.wo = Vec3(0.0f, 1.0f, 0.0f);
  s.diffuse = Vec3(1.0f);
  RayCounters counters;
  TraceContext ctx{scene, settings, counters, SampleStream(1, 0, static_cast<uint64_t>(std::fabs(x) * 1000), 0)};
  return direct_lighting(s, 0, 1.0f, ctx);
}

// A 2 x 2 light facing down at height 4 over the origin; optionally an opaque slab at height 2
// covering x < 0 (its edge straight above the origin).
std::string shadow_scene(bool occluder) {
  return std::string(R"({
    "camera": { "position": [0, 1, 9], "look_at": [0, 0, 0] },
    "materials": { "m": { "kd": 0.5 } },
    "lights": [ { "type": "rect", "corner": [-1, 4, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 2] } ],
    "nodes": [ )") +
         (occluder
              ? R"({ "shape": "cube", "material": "m", "transform": { "translate": [-10, 2, 0], "scale": [10, 0.01, 10] } })"
              : "") +
         "] }";
}

}  // namespace

TEST_CASE("rect light: emits towards edge1 x edge2, Whitted lights like a point light of its colour nearby",
          "[lights]") {
  RectLight down;  // at height 4, facing down: (2,0,0) x (0,0,2) = (0,-4,0)
  down.corner = Vec3(-0.01f, 4.0f, -0.01f);
  down.edge1 = Vec3(0.02f, 0, 0);
  down.edge2 = Vec3(0, 0, 0.02f);
  down.color = Vec3(2.0f);
  CHECK(down.normal().y == Approx(-1.0f));
  // Straight below: the radiance by which its face lights the point (RectLight::lighting_radiance:
  // pi x colour x attenuation x d^2 / area, attenuation 1 here), head-on, drawn with density
  // d^2 / area per solid angle.
  const LightSample below = sample_li(Light(down), Vec3(0.0f), Vec2(0.5f));
  CHECK(below.radiance.x == Approx(2.0f * kPi * 16.0f / 0.0004f));
  CHECK(below.direction.y == Approx(1.0f));
  CHECK(below.distance == Approx(4.0f));
  CHECK(below.cos_light == Approx(1.0f));
  CHECK(below.pdf == Approx(16.0f / 0.0004f));
  CHECK_FALSE(below.delta);
  // At 60 degrees off its normal: the emitter's cosine is a half.
  const LightSample slanted = sample_li(Light(down), Vec3(4.0f * std::sqrt(3.0f), 0.0f, 0.0f), Vec2(0.5f));
  CHECK(slanted.cos_light == Approx(0.5f).epsilon(1e-3));
  CHECK(slanted.pdf == Approx(64.0f / (0.5f * 0.0004f)).epsilon(1e-3));
  // Whitted's rule: colour x attenuation x cos at the light, then Phong at the floor (cos 1
  // below, cos 0.5 at 60 degrees).
  Scene scene;
  scene.lights = {down};
  RenderSettings settings;
  settings.shadow_samples = 1;
  CHECK(floor_light(scene, settings, 0.0f).x == Approx(2.0f));
  CHECK(floor_light(scene, settings, 4.0f * std::sqrt(3.0f)).x == Approx(2.0f * 0.5f * 0.5f).epsilon(1e-3));
  // Above it, nothing, unless two-sided; swapping the edges turns it round.
  CHECK(sample_li(Light(down), Vec3(0, 8, 0), Vec2(0.5f)).pdf == 0.0f);
  RectLight up = down;
  std::swap(up.edge1, up.edge2);
  CHECK(up.normal().y == Approx(1.0f));
  CHECK(sample_li(Light(up), Vec3(0, 8, 0), Vec2(0.5f)).pdf > 0.0f);
  CHECK(sample_li(Light(up), Vec3(0.0f), Vec2(0.5f)).pdf == 0.0f);
  RectLight both = down;
  both.two_sided = true;
  CHECK(sample_li(Light(both), Vec3(0, 8, 0), Vec2(0.5f)).cos_light == Approx(1.0f));
  // Samples cover the rectangle, corner to corner, for skewed edges too.
  RectLight skew = down;
  skew.edge1 = Vec3(1, 0, 0);
  skew.edge2 = Vec3(0.5f, 0, 1);
  CHECK(skew.point(Vec2(1.0f, 1.0f)).x == Approx(skew.corner.x + 1.5f));
  // Rays see the face that emits, inside the parallelogram only.
  Ray ray;
  ray.origin = Vec3(0.6f, 0.0f, 0.5f);
  ray.direction = Vec3(0, 1, 0);
  float t = 0.0f;
  CHECK(intersect_rect(skew, ray, t));
  CHECK(t == Approx(4.0f));
  ray.origin = Vec3(-0.3f, 0.0f, 0.9f);  // left of the slanted edge
  CHECK_FALSE(intersect_rect(skew, ray, t));
  ray.origin = Vec3(0.6f, 8.0f, 0.5f);  // from above: the dark back
  ray.direction = Vec3(0, -1, 0);
  CHECK_FALSE(intersect_rect(skew, ray, t));
}

TEST_CASE("area light samples: each stratum of the grid gets exactly one", "[lights][sampling]") {
  const StratifiedGrid grid(16);
  const SampleStream stream(3, 0, 42, 0);
  int cells[4][4] = {};
  for (int i = 0; i < 16; ++i) {
    const Vec2 p = grid.point(i, stream.get2(SamplePurpose::kLight, 7, static_cast<uint64_t>(i)));
    REQUIRE(p.x >= 0.0f);
    REQUIRE(p.x < 1.0f);
    ++cells[static_cast<int>(p.y * 4)][static_cast<int>(p.x * 4)];
  }
  for (auto& row : cells)
    for (int c : row) CHECK(c == 1);
  // Keyed, not sequential: the same request gives the same numbers, another purpose others.
  CHECK(stream.get2(SamplePurpose::kLight, 7, 3) == stream.get2(SamplePurpose::kLight, 7, 3));
  CHECK(stream.get2(SamplePurpose::kLight, 7, 3) != stream.get2(SamplePurpose::kGlossy, 7, 3));
}

TEST_CASE("a point straight below an occluder's edge sees half the light", "[lights][shadow]") {
  const LoadedScene open = rt::test::load_scene_text("area_open.json", shadow_scene(false));
  const LoadedScene half = rt::test::load_scene_text("area_half.json", shadow_scene(true));
  RenderSettings settings;
  for (const int samples : {16, 64}) {
    settings.shadow_samples = samples;
    const float ratio = floor_light(half.scene, settings, 0.0f).x / floor_light(open.scene, settings, 0.0f).x;
    INFO(samples << " samples: " << ratio);
    // Half the strata lie beyond the edge; jitter within them moves the weights a little.
    CHECK(ratio == Approx(0.5f).margin(samples == 16 ? 0.06 : 0.03));
  }
}

TEST_CASE("the penumbra is as wide as similar triangles say", "[lights][shadow]") {
  // Light 2 wide at height 4, occluder edge at height 2: the penumbra on the floor runs from
  // x = -1 (the whole light hidden) to x = +1 (all of it seen), width W h / (H - h) = 2.
  const LoadedScene open = rt::test::load_scene_text("penumbra_open.json", shadow_scene(false));
  const LoadedScene half = rt::test::load_scene_text("penumbra_half.json", shadow_scene(true));
  RenderSettings settings;
  settings.shadow_samples = 1024;
  float dark_end = -2.0f, lit_start = 2.0f;
  for (float x = -1.5f; x <= 1.5f; x += 0.01f) {
    const float f = floor_light(half.scene, settings, x).x / floor_light(open.scene, settings, x).x;
    if (f <= 0.005f) dark_end = x;
    if (f >= 0.995f && lit_start > 1.9f) lit_start = x;
  }
  INFO("umbra ends at " << dark_end << ", full light from " << lit_start);
  CHECK(dark_end == Approx(-1.0f).margin(0.06));
  CHECK(lit_start == Approx(1.0f).margin(0.06));
}

TEST_CASE("rect lights are seen by camera rays and in mirrors, and cast no shadow", "[lights]") {
  const LoadedScene s = rt::test::load_scene_text("see_light.json", R"({
    "render": { "width": 32, "height": 32 },
    "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40 },
    "lights": [ { "type": "rect", "corner": [-0.5, -0.5, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0],
                  "color": [0.2, 0.4, 0.8] } ], "nodes": [] })");
  Image image;
  render(s.scene, s.settings, image);
  CHECK(image.at(16, 16) == Vec3(0.2f, 0.4f, 0.8f));  // facing +Z, towards the camera
  CHECK(image.at(1, 1) == Vec3(0.0f));                // background beside it
}

TEST_CASE("rect light: the scene's intersection finds its face, so every integrator sees it", "[lights]") {
  // The 2 x 2 light at height 4 facing down, over the slab at height 2.
  const LoadedScene s = rt::test::load_scene_text("rect-found.json", shadow_scene(true));
  // Looking up from below the slab's edge at x = 0.5 (the slab covers x < 0): the light's face.
  Ray up(Vec3(0.5f, 1.0f, 0.5f), Vec3(0.0f, 1.0f, 0.0f));
  SceneHit met;
  REQUIRE(s.scene.intersect(up, met));
  CHECK_FALSE(met.surface);
  REQUIRE(met.light);
  CHECK(up.tmax == Approx(3.0f));
  CHECK(met.light_uv.x == Approx(0.75f));
  CHECK(met.light_uv.y == Approx(0.75f));
  // Under the slab, the slab comes first; the surface-only intersection never reports a light.
  Ray blocked(Vec3(-0.5f, 1.0f, 0.5f), Vec3(0.0f, 1.0f, 0.0f));
  REQUIRE(s.scene.intersect(blocked, met));
  CHECK(met.surface);
  CHECK_FALSE(met.light);
  Ray through(Vec3(0.5f, 1.0f, 0.5f), Vec3(0.0f, 1.0f, 0.0f));
  Hit hit;
  CHECK_FALSE(s.scene.intersect(through, hit));
  // From above, a one-sided light shows its dark back: nothing is met (the slab is at x < 0).
  Ray down(Vec3(0.5f, 6.0f, 0.5f), Vec3(0.0f, -1.0f, 0.0f));
  CHECK_FALSE(s.scene.intersect(down, met));

  // A debug view sees the light with no loop of its own: its normal, (0, -1, 0), mapped to colour.
  const auto normals = make_integrator("normals");
  RayCounters counters;
  TraceContext ctx{s.scene, s.settings, counters, SampleStream(1, 0, 0, 0)};
  const Vec3 seen = normals->radiance(Ray(Vec3(0.5f, 1.0f, 0.5f), Vec3(0.0f, 1.0f, 0.0f)), 0, ctx);
  CHECK(seen.x == Approx(0.5f));
  CHECK(seen.y == Approx(0.0f));
  CHECK(seen.z == Approx(0.5f));
}

TEST_CASE("secondary shadows: an area light's samples follow the hit's weight in the pixel", "[lights][shadow]") {
  CHECK(secondary_shadow_samples(16, 1.0f) == 16);        // a camera ray's hit
  CHECK(secondary_shadow_samples(16, 0.85f) == 14);       // a mirror of 0.85: ceil(13.6)
  CHECK(secondary_shadow_samples(16, 1.0f / 6.0f) == 3);  // one of 6 glossy rays: ceil(2.67)
  CHECK(secondary_shadow_samples(16, 0.001f) == 1);       // never none
  CHECK(secondary_shadow_samples(16, 0.0f) == 1);
  CHECK(secondary_shadow_samples(1, 0.5f) == 1);
  CHECK(secondary_shadow_samples(1024, 1.5f) == 1024);  // never more than asked
  // Its shortcut (single samples, weight 1 or more) gives the rule's own answer (at least one
  // sample asked: the scene's minimum; 0 x infinity would make the rule's own number NaN).
  int checked = 0;
  for (int n = 1; n <= 64; ++n)
    for (const float w : {0.0f, 1e-6f, 0.3f, 0.5f, 0.999999f, 1.0f, 1.000001f, 2.0f, 1e30f, kInfinity}) {
      const float scaled = std::ceil(static_cast<float>(n) * w);
      const int rule = scaled >= static_cast<float>(n) ? n : std::max(1, static_cast<int>(scaled));
      INFO(n << " samples, weight " << w);
      CHECK(secondary_shadow_samples(n, w) == rule);
      ++checked;
    }
  CHECK(checked == 640);

  // A mirror of reflectivity 0.5 facing a lit floor: its hits on the floor take 8 samples of 16.
  const LoadedScene s = rt::test::load_scene_text("mirror_shadows.json", R"({
    "render": { "width": 16, "height": 16, "shadow_samples": 16, "max_depth": 1, "antialias": { "mode": "none" } },
    "camera": { "position": [0, 1, 4], "look_at": [0, 0, 0], "fov": 30 },
    "materials": { "floor": { "kd": 0.7 }, "mirror": { "kd": 0.1, "reflectivity": 0.5 } },
    "lights": [ { "type": "rect", "corner": [-1, 5, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 2] } ],
    "nodes": [ { "shape": "plane", "material": "floor", "transform": { "scale": 20 } },
               { "shape": "sphere", "material": "mirror", "transform": { "translate": [0, 0.6, 0], "scale": 0.6 } } ] })");
  RenderSettings full = s.settings;
  full.scale_secondary_shadows = false;
  Image a, b;
  const RenderStats f = render(s.scene, full, a);
  const RenderStats scaled = render(s.scene, s.settings, b);
  CHECK(scaled.rays[RayKind::kCamera] == f.rays[RayKind::kCamera]);
  CHECK(scaled.rays[RayKind::kReflection] == f.rays[RayKind::kReflection]);
  const uint64_t reflections = f.rays[RayKind::kReflection];
  REQUIRE(reflections > 0);
  // Each reflection that meets the floor (or the sphere itself) saves 8 shadow rays; the rest of
  // the reflections go to the sky.
  const uint64_t saved = f.rays[RayKind::kShadow] - scaled.rays[RayKind::kShadow];
  CHECK(saved > 0);
  CHECK(saved % 8 == 0);
  CHECK(saved <= 8 * reflections);
  // The camera's own hits take all 16 either way: pixels that see no mirror are the same.
  CHECK(a.at(0, 15) == b.at(0, 15));
}

TEST_CASE("rect light: the scene keeps each rect light's frame, the one a sample would work out", "[lights]") {
  const LoadedScene s = rt::test::load_scene_text("rect-frame.json", shadow_scene(true));
  REQUIRE(s.scene.rect_frames.size() == s.scene.lights.size());
  for (size_t l = 0; l < s.scene.lights.size(); ++l) {
    const RectLight* rect = std::get_if<RectLight>(&s.scene.lights[l]);
    if (!rect) continue;
    const RectFrame own(*rect);
    CHECK(s.scene.rect_frame(l).normal_area == own.normal_area);
    CHECK(s.scene.rect_frame(l).area == own.area);
    CHECK(s.scene.rect_frame(l).unit_normal == own.unit_normal);
    CHECK(own.area == Approx(4.0f));  // the 2 x 2 light
    // A scene built by hand, without the table, works it out when asked.
    Scene bare;
    bare.lights = s.scene.lights;
    CHECK(bare.rect_frame(l).normal_area == own.normal_area);
  }
}

TEST_CASE("rect light: a light the ray passes beside leaves the met light's (u, v) alone", "[lights]") {
  // Light 0 at height 4 over (0..1, 0..1); light 1 at height 3, far to the side: the ray up from
  // (0.5, 1, 0.5) crosses light 1's plane first, outside its rectangle, and meets light 0.
  RectLight met_light, beside;
  met_light.corner = Vec3(0.0f, 4.0f, 0.0f);
  met_light.edge1 = Vec3(1.0f, 0.0f, 0.0f);
  met_light.edge2 = Vec3(0.0f, 0.0f, 1.0f);
  beside = met_light;
  beside.corner = Vec3(5.0f, 3.0f, 5.0f);
  Scene scene;
  scene.lights = {met_light, beside};
  Ray up(Vec3(0.25f, 1.0f, 0.75f), Vec3(0.0f, 1.0f, 0.0f));
  SceneHit met;
  REQUIRE(scene.intersect(up, met));
  REQUIRE(met.light == &std::get<RectLight>(scene.lights[0]));
  CHECK(met.light_uv.x == Approx(0.25f));
  CHECK(met.light_uv.y == Approx(0.75f));
}
