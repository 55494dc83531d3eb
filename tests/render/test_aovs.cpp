// The first hit's layers (core/render/aovs.h: albedo, normal, depth), filled by the integrator
// that renders the colour, in the same pass, averaged by the same pixel sampler: the colour and
// the rays traced are those of a render without them, for every pixel sampler and integrator.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "tests/support/loading.h"

using namespace rt;

namespace {

// A red floor (kd 0.8, 0.2, 0.1) seen from above at a slant, a grey ball on it, sky behind.
const char* kScene = R"({
  "render": { "width": 40, "height": 30, "samples_per_pixel": 16, "max_depth": 3 },
  "camera": { "position": [0, 2, 6], "look_at": [0, 1.2, 0], "fov": 40 },
  "background": [0.3, 0.4, 0.5],
  "materials": { "floor": { "kd": [0.8, 0.2, 0.1] }, "ball": { "kd": 0.5, "reflectivity": 0.3 } },
  "lights": [ { "type": "point", "position": [2, 5, 3] } ],
  "nodes": [ { "shape": "plane", "material": "floor", "transform": { "scale": 30 } },
             { "shape": "sphere", "material": "ball", "transform": { "translate": [0, 1, 0] } } ]
})";

struct Pass {
  Film film;
  RenderStats stats;
};

Pass render_pass(const LoadedScene& s, const RenderSettings& settings, bool aovs) {
  Pass p;
  RenderView view;
  view.aovs = aovs;
  p.stats = render(s.scene, settings, p.film, {}, 0, view);
  return p;
}

}  // namespace

TEST_CASE("AOVs: filled in the same pass, the colour and the rays unchanged, every sampler and integrator",
          "[render][aov]") {
  const LoadedScene s = rt::test::load_scene_text("aovs.json", kScene);
  struct Case {
    const char* integrator;
    const char* antialias;
  };
  const Case cases[] = {
      {"whitted", "none"}, {"whitted", "uniform"}, {"whitted", "adaptive"}, {"path", "none"}, {"normals", "adaptive"}};
  for (const Case& c : cases) {
    RenderSettings settings = s.settings;
    settings.integrator = c.integrator;
    settings.antialias.mode = c.antialias;
    settings.antialias.samples = 3;
    settings.antialias.jitter = true;
    INFO(c.integrator << ", anti-aliasing " << c.antialias);
    const Pass plain = render_pass(s, settings, false);
    const Pass with = render_pass(s, settings, true);
    CHECK_FALSE(plain.film.has_aovs());
    REQUIRE(with.film.has_aovs());
    CHECK(with.film.color.pixels == plain.film.color.pixels);
    CHECK(with.film.samples == plain.film.samples);
    CHECK(with.stats.rays.total() == plain.stats.rays.total());  // no second render
    // The floor's centre pixels show its kd; the corners above the horizon the sky: nothing met.
    const Film& f = with.film;
    const size_t floor = f.index(20, 28), sky = f.index(0, 0);
    CHECK(f.albedo.pixels[floor].x == Approx(0.8f));
    CHECK(f.albedo.pixels[floor].y == Approx(0.2f));
    CHECK(f.normal.pixels[floor].y == Approx(1.0f));
    CHECK(f.distance[sky] == Aovs::kFarAway);
    CHECK(f.normal.pixels[sky] == Vec3(0.0f));
    // Every normal is an average of unit vectors; every distance a surface's or far away.
    int blended = 0;
    for (size_t i = 0; i < f.distance.size(); ++i) {
      CHECK(glm::length(f.normal.pixels[i]) <= 1.0001f);
      CHECK(((f.distance[i] > 2.0f && f.distance[i] < 100.0f) || f.distance[i] == Aovs::kFarAway));
      blended += glm::length(f.normal.pixels[i]) < 0.99f && glm::length(f.normal.pixels[i]) > 0.01f;
    }
    // Pixels across the ball's outline average its normals with the floor's, except for one ray
    // through each pixel's centre.
    if (std::string(c.antialias) != "none" || std::string(c.integrator) == "path") CHECK(blended > 0);
  }
}

TEST_CASE("AOVs: the adaptive sampler's shared corners carry their layers across tiles, on any thread count",
          "[render][aov][antialias]") {
  const LoadedScene s = rt::test::load_scene_text("aovs.json", kScene);
  RenderSettings whole = s.settings;
  whole.antialias.mode = "adaptive";
  whole.antialias.max_depth = 3;
  whole.tile_size = 64;  // one tile: no border handed on
  whole.threads = 1;
  const Pass one = render_pass(s, whole, true);
  RenderSettings tiled = whole;
  tiled.tile_size = 7;  // 6 x 5 tiles, each taking its left and upper neighbours' borders
  for (const int threads : {1, 3}) {
    tiled.threads = threads;
    const Pass many = render_pass(s, tiled, true);
    INFO(threads << " threads");
    CHECK(many.film.color.pixels == one.film.color.pixels);
    CHECK(many.film.albedo.pixels == one.film.albedo.pixels);
    CHECK(many.film.normal.pixels == one.film.normal.pixels);
    CHECK(many.film.emission.pixels == one.film.emission.pixels);
    CHECK(many.film.distance == one.film.distance);
    CHECK(many.film.samples == one.film.samples);
  }
}

TEST_CASE("AOVs: a pixel's depth is the nearest surface any of its samples met", "[render][aov]") {
  const LoadedScene s = rt::test::load_scene_text("aovs.json", kScene);
  RenderSettings settings = s.settings;
  settings.integrator = "path";
  const Pass with = render_pass(s, settings, true);
  RenderSettings centre = s.settings;  // one ray through each pixel's centre
  centre.antialias.mode = "none";
  const Pass one = render_pass(s, centre, true);
  for (size_t i = 0; i < with.film.distance.size(); ++i) CHECK(with.film.distance[i] <= one.film.distance[i] * 1.02f);
}

TEST_CASE("AOVs: the path tracer's layers see through mirrors and clear glass, as a denoiser needs them",
          "[render][aov][denoise]") {
  // A perfect mirror filling the view reflects the red floor: the layers at the centre are the
  // floor's (its albedo tinted by the mirror's 0.9, its normal, the whole path's length), and
  // the emission layer holds the sky the mirror shows, so a denoiser keeps the reflection sharp.
  const LoadedScene s = rt::test::load_scene_text("aov_mirror.json", R"({
  "render": { "width": 9, "height": 9, "samples_per_pixel": 4, "max_depth": 3, "integrator": "path" },
  "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 10 },
  "background": [0.3, 0.4, 0.5],
  "materials": { "mirror": { "kd": 0, "ks": 0, "reflectivity": 0.9 }, "red": { "kd": [0.8, 0.1, 0.1] } },
  "nodes": [ { "shape": "plane", "material": "mirror", "transform": { "rotate": [-45, 0, 0], "scale": 20 } },
             { "shape": "plane", "material": "red", "transform": { "translate": [0, -3, 0], "scale": 50 } } ]
})");
  const Pass p = render_pass(s, s.settings, true);
  const size_t centre = p.film.index(4, 4);
  // The camera looks down -z at a mirror tilted 45 degrees: the ray turns down to the floor.
  const Vec3 albedo = p.film.albedo.pixels[centre];
  CHECK(albedo.x == Approx(0.9f * 0.8f).epsilon(0.01));
  CHECK(albedo.y == Approx(0.9f * 0.1f).epsilon(0.01));
  CHECK(p.film.normal.pixels[centre].y == Approx(1.0f).epsilon(0.01));
  CHECK(p.film.distance[centre] == Approx(5.0f + 3.0f).epsilon(0.02));
  CHECK(p.film.emission.pixels[centre] == Vec3(0.0f));
}
