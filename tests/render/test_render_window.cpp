// Part of the image (--crop, --tile): every pixel of a window is the whole render's, for every
// pixel sampler and both integrators, whatever the window's corner, size and tile size.
#include <catch2/catch.hpp>

#include "core/render/band_split.h"
#include "core/render/renderer.h"
#include "io/scene_loader.h"
#include "tests/support/loading.h"
#include "tests/support/render_cases.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

LoadedScene load(const std::string& path) { return rt::test::load_scene_file(path); }

}  // namespace

TEST_CASE("a window of the image renders the whole render's pixels", "[render][window]") {
  // A window's border pixels compute their own lattice samples and must still agree.
  for (const rt::test::RenderCase& c : rt::test::kRenderCases) {
    INFO(c.scene << " " << c.integrator << " " << c.antialias);
    auto [s, settings] = rt::test::load_render_case(c, 67, 41);
    settings.threads = 2;
    Film whole;
    render(s.scene, settings, whole);
    for (const PixelWindow w : {PixelWindow{0, 0, 67, 41}, PixelWindow{13, 7, 50, 29}, PixelWindow{66, 40, 67, 41},
                                PixelWindow{0, 20, 67, 21}, PixelWindow{31, 0, 32, 41}}) {
      for (const int tile : {5, 16}) {
        INFO("window " << w.x0 << "," << w.y0 << "," << w.x1 << "," << w.y1 << ", tile " << tile);
        settings.tile_size = tile;
        Film part;
        render(s.scene, settings, part, {}, 0, RenderView{nullptr, 0, w});
        REQUIRE(part.width() == w.width());
        REQUIRE(part.height() == w.height());
        CHECK(part.window() == w);
        int differing = 0;
        for (int y = w.y0; y < w.y1; ++y)
          for (int x = w.x0; x < w.x1; ++x) {
            differing += part.color.at(x - w.x0, y - w.y0) != whole.color.at(x, y);
            differing += part.samples[part.index(x - w.x0, y - w.y0)] != whole.samples[whole.index(x, y)];
          }
        CHECK(differing == 0);
      }
    }
  }
}

TEST_CASE("bands of rows follow the cumulative cost", "[render][window]") {
  CHECK(band_edges({1, 1, 1, 1}, 8, 2) == std::vector<int>{0, 4, 8});
  CHECK(band_edges({3, 1, 1, 1}, 4, 2) == std::vector<int>{0, 1, 4});     // half the cost in the first row
  CHECK(band_edges({0, 0, 6, 0}, 8, 3) == std::vector<int>{0, 5, 6, 8});  // all of it in rows 4-5
  CHECK(band_edges({0, 0}, 9, 3) == std::vector<int>{0, 3, 6, 9});        // nothing measured: equal heights
  CHECK(band_edges({5}, 3, 3) == std::vector<int>{0, 1, 2, 3});           // a row each at least
}

TEST_CASE("cost-balanced bands cover the image once, the same every time", "[render][window]") {
  const LoadedScene s = load(rt::test::source_path("scenes/primitives.json"));
  RenderSettings settings = s.settings;
  settings.width = 160;
  settings.height = 90;
  const std::vector<PixelWindow> bands = cost_balanced_bands(s.scene, settings, 7);
  REQUIRE(bands.size() == 7);
  int y = 0;
  for (const PixelWindow& b : bands) {
    CHECK(b.x0 == 0);
    CHECK(b.x1 == 160);
    CHECK(b.y0 == y);
    CHECK(b.y1 > b.y0);
    y = b.y1;
  }
  CHECK(y == 90);
  settings.threads = 1;
  CHECK(cost_balanced_bands(s.scene, settings, 7) == bands);
}

TEST_CASE("a window outside the image is refused", "[render][window]") {
  const LoadedScene s = load(rt::test::source_path("tests/data/golden_tiny.json"));
  Film film;
  CHECK_THROWS_AS(
      render(s.scene, s.settings, film, {}, 0, RenderView{nullptr, 0, PixelWindow{0, 0, s.settings.width + 1, 1}}),
      std::invalid_argument);
}
