// A film that keeps only display codes (RenderView::display8, what `rtcli render -o X.png` asks
// for): its bytes are exactly the encoding of the linear film's colour, for both integrators,
// every display transform, a window, tiles narrower and wider than the encoder's runs, and any
// thread count.
#include <stdexcept>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "io/image/rgb8_image.h"
#include "io/scene_loader.h"
#include "tests/support/loading.h"
#include "tests/support/render_cases.h"
#include "tests/support/test_paths.h"

using namespace rt;

TEST_CASE("a film of display codes holds the linear film's colour, encoded", "[render][display8]") {
  for (const rt::test::RenderCase& c : rt::test::kRenderCases) {
    auto [s, settings] = rt::test::load_render_case(c, 150, 31);  // wider than the encoder's runs of 64
    for (const DisplayTransform display :
         {DisplayTransform{}, DisplayTransform{1.3f, ToneMap::kFilmic}, DisplayTransform{-2.0f, ToneMap::kClamp}}) {
      for (const PixelWindow w : {PixelWindow{}, PixelWindow{13, 7, 141, 29}}) {
        for (const int tile : {5, 100}) {
          for (const unsigned threads : {1u, 3u}) {
            INFO(c.scene << " exposure " << display.exposure << ", window " << w.x0 << "," << w.y0 << ", tile " << tile
                         << ", threads " << threads);
            settings.tile_size = tile;
            settings.threads = threads;
            Film linear, codes;
            render(s.scene, settings, linear, {}, 0, RenderView{nullptr, 0, w});
            RenderView view{nullptr, 0, w};
            view.display8 = &display;
            render(s.scene, settings, codes, {}, 0, view);
            CHECK(codes.color.pixels.empty());
            REQUIRE(codes.width() == linear.width());
            REQUIRE(codes.height() == linear.height());
            const Rgb8Image expected = encode_srgb8(linear.color, display);
            REQUIRE(codes.display8.size() == expected.rgb.size());
            size_t differing = 0;
            for (size_t i = 0; i < expected.rgb.size(); ++i) differing += codes.display8[i] != expected.rgb[i];
            CHECK(differing == 0);
          }
        }
      }
    }
  }
}

TEST_CASE("a film of display codes is refused where the linear colour is needed", "[render][display8]") {
  const LoadedScene s = rt::test::load_scene_file(rt::test::source_path("scenes/cornell_box.json"));
  RenderSettings settings = s.settings;
  settings.width = settings.height = 8;
  const DisplayTransform display;
  RenderView view;
  view.display8 = &display;
  view.aovs = true;
  Film film;
  CHECK_THROWS_AS(render(s.scene, settings, film, {}, 0, view), std::invalid_argument);
  view.aovs = false;
  RenderControl control;
  control.pass_done = [](const Film&, int) {};
  CHECK_THROWS_AS(render(s.scene, settings, film, control, 0, view), std::invalid_argument);
}
