// The adaptive pixel sampler: where it refines, how many rays it traces with corners shared,
// and that its image depends on nothing but the scene, the settings and the seed.
#include <string>

#include <functional>
#include <string>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "io/image/rgb8_image.h"
#include "io/scene_loader.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

// A 20 x 20 view (fov 90 at distance 5: world x = px / 2 - 5). With `edge`, a white half-plane
// (ambient 1, kd 1) covers the pixel columns left of x = 10.3; without, the plane covers all.
LoadedScene half_plane(const std::string& antialias, bool edge = true) {
  const std::string transform =
      edge ? R"({ "translate": [-24.925, 0, -5], "rotate": [90, 0, 0], "scale": [25.075, 1, 50] })"
           : R"({ "translate": [0, 0, -5], "rotate": [90, 0, 0], "scale": [50, 1, 50] })";
  // One file name per content: ctest runs test cases as parallel processes, and two of them
  // writing the same file under each other made the edge test read the flat scene.
  const std::string name =
      "adaptive_half_plane_" + std::to_string(std::hash<std::string>{}(antialias + transform)) + ".json";
  return rt::test::load_scene_text(name, R"({
      "render": { "width": 20, "height": 20, "antialias": )" +
                                             antialias +
                                             R"( },
      "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 90 },
      "ambient": 1, "materials": { "white": { "kd": 1 } },
      "nodes": [ { "shape": "plane", "material": "white", "transform": )" +
                                             transform + " } ] }");
}

struct Rendered {
  Film film;
  RenderStats stats;
};

Rendered render_film(const LoadedScene& s, unsigned threads = 1, int tile = 32) {
  RenderSettings settings = s.settings;
  settings.threads = threads;
  settings.tile_size = tile;
  Rendered r;
  r.stats = render(s.scene, settings, r.film);
  return r;
}

}  // namespace

TEST_CASE("adaptive: a flat-coloured image is not refined, each pixel averages its four shared corners",
          "[render][antialias][adaptive]") {
  const Rendered r = render_film(half_plane(R"({ "mode": "adaptive", "threshold": 0, "max_depth": 3 })", false), 2, 7);
  for (size_t i = 0; i < r.film.depth.size(); ++i) {
    CHECK(r.film.depth[i] == 0);
    CHECK(r.film.samples[i] == 4);
  }
  CHECK(r.film.color.at(13, 4).x == 1.0f);
  CHECK(r.stats.rays[RayKind::kCamera] == 21u * 21u);  // one ray per lattice point, (W + 1) x (H + 1)
}

TEST_CASE("adaptive: a vertical edge refines only the pixels on it, and they converge to the covered fraction",
          "[render][antialias][adaptive]") {
  const Rendered r = render_film(half_plane(R"({ "mode": "adaptive", "threshold": 0.1, "max_depth": 4 })"));
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      INFO("pixel " << x << ", " << y);
      CHECK(r.film.depth[r.film.index(x, y)] == (x == 10 ? 4 : 0));
    }
  // On the 16 x 16 lattice the edge (0.3 into the pixel) lies in cell 4: four covered cells and
  // one half-covered (two of its corners in) of sixteen: 4.5 / 16.
  CHECK(r.film.color.at(10, 7).x == Approx(4.5f / 16));
  CHECK(r.film.color.at(9, 7).x == 1.0f);
  CHECK(r.film.color.at(11, 7).x == 0.0f);
}

TEST_CASE("adaptive: with corners shared, every lattice point is traced once, across tile borders too",
          "[render][antialias][adaptive]") {
  // max_depth 2 on the edge at 10.3. Pixel 10 of each row splits once (x 10, 10.5, 11 at y 0,
  // 0.5, 1), then both left cells again (x 10, 10.25, 10.5 at y 0, 0.25, ..., 1). Beyond the
  // 21 x 21 pixel corners that is 10 points inside each pixel (x 10: 3, x 10.25: 3, x 10.5: 3,
  // x 11: 1) and 2 on each of the 21 horizontal pixel borders (x 10.25 and 10.5).
  const uint64_t expected = 21 * 21 + 20 * 10 + 21 * 2;
  const LoadedScene s = half_plane(R"({ "mode": "adaptive", "threshold": 0.1, "max_depth": 2 })");
  for (const auto& [threads, tile] : {std::pair{1u, 32}, std::pair{2u, 7}, std::pair{3u, 1}, std::pair{2u, 10}}) {
    INFO("threads " << threads << ", tile " << tile);
    const Rendered r = render_film(s, threads, tile);
    CHECK(r.stats.rays[RayKind::kCamera] == expected);
    CHECK(r.film.samples[r.film.index(10, 5)] == 18);  // the points its cells use
    CHECK(r.film.samples[r.film.index(9, 5)] == 4);
  }
}

TEST_CASE("adaptive: centre positions take four rays per cell, shared with nothing", "[render][antialias][adaptive]") {
  const Rendered flat =
      render_film(half_plane(R"({ "mode": "adaptive", "max_depth": 3, "positions": "centres" })", false), 2, 5);
  CHECK(flat.stats.rays[RayKind::kCamera] == 20u * 20u * 4u);
  const Rendered edge = render_film(half_plane(R"({ "mode": "adaptive", "max_depth": 4, "positions": "centres" })"));
  // Centres of pixel 10's quarters: 10.25 is covered, 10.75 not: split. Of the left quarter's:
  // 10.125 in, 10.375 out: split. Then both centres of [10.25, 10.5] (10.3125, 10.4375) miss the
  // edge at 10.3, so refinement stops at depth 2 with a quarter covered: centres can step over
  // an edge that corners bracket (docs/rendering.md, "Anti-aliasing").
  CHECK(edge.film.depth[edge.film.index(10, 3)] == 2);
  CHECK(edge.film.depth[edge.film.index(9, 3)] == 0);
  CHECK(edge.film.color.at(10, 3).x == Approx(0.25f));
  CHECK(edge.film.samples[edge.film.index(10, 3)] == 4 + 4 * 4 + 8 * 4);  // cells visited at depth 0, 1, 2
}

TEST_CASE("adaptive: the image is the same for any thread count and tile size", "[render][antialias][determinism]") {
  // The anti-aliasing scene with a lens, so that every corner also has a keyed lens sample.
  for (const char* positions : {"corners", "centres"}) {
    INFO(positions);
    LoadedScene s = [&] {
      Diagnostics diags;
      auto loaded = load_scene(rt::test::source_path("scenes/antialias.json"), rt::test::load_options(), diags);
      REQUIRE(loaded);
      return std::move(*loaded);
    }();
    s.scene.camera.aperture = 0.03f;
    RenderSettings& settings = s.settings;
    settings.width = 120;
    settings.height = 68;
    settings.antialias.max_depth = 3;
    settings.antialias.positions =
        std::string(positions) == "corners" ? SamplePositions::kCorners : SamplePositions::kCentres;
    const Rendered reference = render_film(s, 1, 32);
    CHECK(reference.stats.rays[RayKind::kCamera] > 121u * 69u);
    for (const auto& [threads, tile] : {std::pair{2u, 32}, std::pair{3u, 7}, std::pair{2u, 1}, std::pair{4u, 50}}) {
      INFO("threads " << threads << ", tile " << tile);
      const Rendered r = render_film(s, threads, tile);
      CHECK(encode_srgb8(r.film.color).rgb == encode_srgb8(reference.film.color).rgb);
      CHECK(r.film.depth == reference.film.depth);
      CHECK(r.stats.rays[RayKind::kCamera] == reference.stats.rays[RayKind::kCamera]);
    }
  }
}

TEST_CASE("render statistics: the refined pixels and camera samples are the film's whether it keeps them or not",
          "[render][antialias][adaptive]") {
  LoadedScene s = [&] {
    Diagnostics diags;
    auto loaded = load_scene(rt::test::source_path("scenes/antialias.json"), rt::test::load_options(), diags);
    REQUIRE(loaded);
    return std::move(*loaded);
  }();
  s.settings.width = 96;
  s.settings.height = 54;
  for (const auto& [threads, tile] : {std::pair{1u, 32}, std::pair{3u, 7}}) {
    INFO("threads " << threads << ", tile " << tile);
    s.settings.threads = threads;
    s.settings.tile_size = tile;
    for (const PixelWindow window : {PixelWindow{}, PixelWindow{10, 5, 71, 40}}) {
      RenderView view;
      view.window = window;
      Film kept;
      const RenderStats with = render(s.scene, s.settings, kept, {}, 0, view);
      PixelTotals counted;
      for (size_t i = 0; i < kept.samples.size(); ++i) {
        counted.refined += kept.depth[i] > 0;
        counted.samples += kept.samples[i];
      }
      CHECK(counted.refined > 0);
      CHECK(with.pixels.refined == counted.refined);
      CHECK(with.pixels.samples == counted.samples);
      view.pixel_counts = false;
      Film bare;
      const RenderStats without = render(s.scene, s.settings, bare, {}, 0, view);
      CHECK(bare.samples.empty());
      CHECK(bare.depth.empty());
      CHECK(bare.color.pixels == kept.color.pixels);
      CHECK(without.pixels.refined == counted.refined);
      CHECK(without.pixels.samples == counted.samples);
    }
  }
}
