// GIF output: frame delays, the median-cut palette, dithering, and files read back with giflib.
#include <catch2/catch.hpp>

#include <fstream>
#include <set>

#include "cli/frames/frame_list.h"
#include "cli/frames/frame_output.h"
#include "io/image/color_quantiser.h"
#include "io/image/gif_file.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

Rgb8Image gradient(int w, int h, int phase = 0) {
  Rgb8Image img{w, h, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.rgb.insert(img.rgb.end(), {static_cast<uint8_t>((x * 255 / (w - 1) + phase) % 256),
                                     static_cast<uint8_t>(y * 255 / (h - 1)), static_cast<uint8_t>(128)});
  return img;
}

double rms_error(const Rgb8Image& a, const IndexedImage& q) {
  double sum = 0;
  for (size_t p = 0; p < q.indices.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.rgb[3 * p + static_cast<size_t>(c)]) - q.palette[q.indices[p]][static_cast<size_t>(c)];
      sum += d * d;
    }
  return std::sqrt(sum / (3.0 * static_cast<double>(q.indices.size())));
}

}  // namespace

TEST_CASE("gif: frame delays add up to the loop's length in hundredths", "[gif]") {
  const std::vector<int> d = gif_frame_delays(120, 30.0f);
  REQUIRE(d.size() == 120);
  CHECK(d[0] == 3);
  CHECK(d[1] == 4);
  CHECK(d[2] == 3);
  int total = 0;
  for (const int x : d) total += x;
  CHECK(total == 400);  // 120 frames at 30 fps: 4 s
  CHECK(gif_frame_delays(3, 25.0f) == std::vector<int>{4, 4, 4});
  CHECK(gif_frame_delays(2, 1000.0f) == std::vector<int>{1, 1});  // never 0 (browsers slow those down)
}

TEST_CASE("gif: median cut keeps few colours exactly and spreads many over the palette", "[gif]") {
  Rgb8Image few{4, 1, {255, 0, 0, 0, 255, 0, 255, 0, 0, 10, 20, 30}};
  const IndexedImage q = quantise(few, false);
  CHECK(q.palette.size() == 3);
  CHECK(rms_error(few, q) == 0.0);

  const Rgb8Image g = gradient(256, 256);  // 65,536 colours
  const IndexedImage plain = quantise(g, false);
  CHECK(plain.palette.size() == 256);
  // 256 boxes over a 256 x 256 square of colours: each about 16 x 16 levels, so errors of a few levels.
  CHECK(rms_error(g, plain) < 4.0);
  std::set<int> used(plain.indices.begin(), plain.indices.end());
  CHECK(used.size() > 240);

  // Dithering keeps the local average: over 8 x 8 blocks it matches the image better than the plain mapping.
  const IndexedImage dithered = quantise(g, true);
  const auto block_error = [&](const IndexedImage& q2) {
    double sum = 0;
    for (int by = 0; by < 256; by += 8)
      for (int bx = 0; bx < 256; bx += 8) {
        double want = 0, got = 0;
        for (int y = by; y < by + 8; ++y)
          for (int x = bx; x < bx + 8; ++x) {
            const size_t p = static_cast<size_t>(y * 256 + x);
            want += g.rgb[3 * p];
            got += q2.palette[q2.indices[p]][0];
          }
        sum += std::fabs(want - got) / 64;
      }
    return sum / (32 * 32);
  };
  CHECK(block_error(dithered) < block_error(plain));
}

TEST_CASE("gif: a written animation reads back with its frames, size, delays and loop", "[gif]") {
  const std::string path = rt::test::output_path("three.gif");
  GifWriter writer(40, 30, false);
  std::string error;
  const std::vector<int> delays = gif_frame_delays(3, 30.0f);
  for (int f = 0; f < 3; ++f)
    REQUIRE(writer.add_frame(gradient(40, 30, 80 * f), delays[static_cast<size_t>(f)], error));
  REQUIRE(writer.finish(path, error));
  GifSummary gif;
  REQUIRE(read_gif(path, gif, error));
  CHECK(gif.width == 40);
  CHECK(gif.height == 30);
  CHECK(gif.frames == 3);
  CHECK(gif.delays == delays);
  CHECK(gif.loops);
  REQUIRE(gif.images.size() == 3);
  CHECK(gif.images[0].rgb != gif.images[1].rgb);
  // 40 x 30 = 1,200 colours into 256: each frame close to what it was given.
  const Rgb8Image want = gradient(40, 30, 80);
  double worst = 0;
  for (size_t i = 0; i < want.rgb.size(); ++i)
    worst = std::max(worst, std::fabs(double(want.rgb[i]) - gif.images[1].rgb[i]));
  CHECK(worst < 24);
}

TEST_CASE("gif: frame lists and numbered names", "[gif][cli]") {
  std::string error;
  const auto frames = [&](const std::string& text) { return parse_frame_list(text, error); };
  CHECK(frames("0-119")->count() == 120);
  CHECK(frames("7")->first() == 7);
  CHECK(frames("-5--1")->first() == -5);
  CHECK(frames("-5--1")->last() == -1);
  CHECK(frames("1-120x10")->frames == std::vector<int>{1, 11, 21, 31, 41, 51, 61, 71, 81, 91, 101, 111});
  CHECK(frames("1,5,9-12")->frames == std::vector<int>{1, 5, 9, 10, 11, 12});
  CHECK(frames("9-12,1,5,10")->frames == std::vector<int>{1, 5, 9, 10, 11, 12});  // sorted, each once
  CHECK(frames("1-120x10")->text() == "1-111x10");
  CHECK(frames("1,5,9-12")->text() == "1,5,9-12");
  CHECK(frames("0-11")->chunk(0, 4).text() == "0-2");
  CHECK(frames("0-11")->chunk(3, 4).text() == "9-11");
  CHECK(frames("0-9")->chunk(0, 4).text() == "0-2");  // 3, 3, 2, 2
  CHECK(frames("0-9")->chunk(3, 4).text() == "8-9");
  CHECK(frames("0-2")->chunk(3, 4).frames.empty());
  for (const char* bad : {"9-3", "a-b", "", "1,,2", "1-5x0", "5x2", "1-2000000", "0-999999", "+3", "1-5x"}) {
    INFO(bad);
    CHECK_FALSE(frames(bad));
  }
  CHECK_THAT(error, Catch::Contains("1-5x"));
  CHECK(sequence_path("out/frame_####.png", 7) == "out/frame_0007.png");
  CHECK(sequence_path("f#.png", 123) == "f123.png");
  CHECK(sequence_path("f###.png", -4) == "f-004.png");
}

TEST_CASE("cli: --frames renders an animated GIF and numbered PNGs, bad ranges and names are refused", "[gif][cli]") {
  const std::string gif = rt::test::output_path("cli_turn.gif");
  auto r = rt::test::rtcli("render scenes/turntable.json --frames 0-2 --width 32 --height 24 --shadow-samples 1 -o '" +
                           gif + "'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("frames 0-2 (3)") && Catch::Contains("per frame"));
  GifSummary summary;
  std::string error;
  REQUIRE(read_gif(gif, summary, error));
  CHECK(summary.frames == 3);
  CHECK(summary.width == 32);
  CHECK(summary.delays == std::vector<int>{3, 4, 3});

  const std::string pattern = rt::test::output_path("cli_turn_###.png");
  r = rt::test::rtcli("render scenes/turntable.json --frames 4-5 --width 16 --height 12 --shadow-samples 1 -o '" +
                      pattern + "'");
  REQUIRE(r.code == 0);
  CHECK(std::ifstream(rt::test::output_path("cli_turn_004.png")).good());
  CHECK(std::ifstream(rt::test::output_path("cli_turn_005.png")).good());

  r = rt::test::rtcli("render scenes/turntable.json --frames 5-2 -o x.gif");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--frames: \"5-2\": expected A <= B"));
  r = rt::test::rtcli("render scenes/turntable.json --frames 0-9 -o '" + rt::test::output_path("one.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("10 frames need an animated GIF"));
  r = rt::test::rtcli("render scenes/turntable.json --frame 3 --frames 0-9");
  CHECK(r.code == 2);
}

TEST_CASE("cli: a GIF without --frames shows the scene's animation, --frames beyond it warns", "[gif][cli]") {
  const std::string scene = rt::test::write_file("spin_short.json", R"({
    "render": {"width": 16, "height": 12},
    "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], "fov": 45},
    "lights": [{"type": "point", "position": [2, 4, 3]}],
    "materials": {"grey": {"kd": 0.5}},
    "nodes": [{"name": "box", "shape": "cube", "material": "grey"}],
    "animation": {"fps": 10, "frames": [2, 6],
                  "tracks": [{"node": "box", "property": "rotate",
                              "keys": [{"frame": 2, "value": {"axis": [0, 1, 0], "degrees": 0}},
                                       {"frame": 6, "value": {"axis": [0, 1, 0], "degrees": 90}}]}]}
  })");
  const std::string gif = rt::test::output_path("spin_short.gif");
  auto r = rt::test::rtcli("render '" + scene + "' -o '" + gif + "'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("frames 2-6 (5)"));
  GifSummary summary;
  std::string error;
  REQUIRE(read_gif(gif, summary, error));
  CHECK(summary.frames == 5);
  CHECK(summary.delays == std::vector<int>{10, 10, 10, 10, 10});
  // Numbered PNGs too; a lone PNG is the first frame.
  r = rt::test::rtcli("render '" + scene + "' -o '" + rt::test::output_path("spin_short_#.png") + "'");
  CHECK_THAT(r.output, Catch::Contains("frames 2-6 (5)"));
  r = rt::test::rtcli("render '" + scene + "' -o '" + rt::test::output_path("spin_short.png") + "'");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, !Catch::Contains("frames"));
  // Asked for more than the animation: rendered, with a warning naming its range.
  r = rt::test::rtcli("render '" + scene + "' --frames 0-9 -o '" + gif + "'");
  CHECK(r.code == 0);
  CHECK_THAT(r.output,
             Catch::Contains("warning: --frames 0-9 goes beyond the scene's animation, frames 2-6 (at 10 fps)"));
  r = rt::test::rtcli("render '" + scene + "' --frames 3-5 -o '" + gif + "'");
  CHECK_THAT(r.output, !Catch::Contains("warning"));
}
