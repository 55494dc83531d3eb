// Cameras and stereo from the command line: what each --stereo mode writes, the same bytes for
// any thread count with every projection and mode, and what is refused.
#include <filesystem>

#include <catch2/catch.hpp>

#include "io/image/png_file.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;
using rt::test::output_path;
using rt::test::read_file;
using rt::test::rtcli;
using rt::test::Run;
using rt::test::write_file;

namespace {

// A small scene with the given camera keys (position and look_at included).
std::string scene(const std::string& name, const std::string& camera) {
  return write_file(name, R"({"render": {"width": 40, "height": 20},
    "camera": {"position": [0, 1, 5], "look_at": [0, 0.5, 0], )" +
                              camera + R"(},
    "materials": {"m": {"kd": [0.8, 0.4, 0.2], "ks": 0.3}, "floor": {"kd": 0.6}},
    "lights": [{"type": "point", "position": [2, 4, 3]}],
    "nodes": [{"shape": "sphere", "material": "m", "transform": {"translate": [0, 0.5, 0], "scale": 0.5}},
              {"shape": "cube", "material": "m", "transform": {"translate": [1.2, 0.3, 1.5], "scale": 0.3}},
              {"shape": "plane", "material": "floor", "transform": {"scale": 6}}]})");
}

std::pair<int, int> size_of(const std::string& png) {
  std::string error;
  const auto image = rt::read_png(png, error);
  REQUIRE(image);
  return {image->width, image->height};
}

}  // namespace

TEST_CASE("cli cameras: each stereo mode writes its layout, pair writes two files", "[cli][stereo]") {
  const std::string s = scene("stereo-modes.json", R"("fov": 40)");
  const std::pair<const char*, std::pair<int, int>> modes[] = {
      {"anaglyph", {40, 20}}, {"side_by_side", {80, 20}}, {"top_bottom", {40, 40}}};
  for (const auto& [mode, size] : modes) {
    INFO(mode);
    const std::string out = output_path(std::string("stereo-") + mode + ".png");
    const Run r = rtcli("render '" + s + "' --stereo " + mode + " -o '" + out + "'");
    REQUIRE(r.code == 0);
    CHECK_THAT(r.output, Catch::Contains("stereo: each eye rendered at 40x20"));
    CHECK(size_of(out) == size);
  }
  const std::string view = output_path("view.png");
  fs::remove(view);
  const Run r = rtcli("render '" + s + "' --stereo pair -o '" + view + "'");
  REQUIRE(r.code == 0);
  CHECK(fs::exists(output_path("view-left.png")));
  CHECK(fs::exists(output_path("view-right.png")));
  CHECK_FALSE(fs::exists(view));
  CHECK(read_file(output_path("view-left.png")) != read_file(output_path("view-right.png")));
  // The left eye of a pair is the left half of side by side.
  std::string error;
  const auto left = rt::read_png(output_path("view-left.png"), error);
  const auto sbs = rt::read_png(output_path("stereo-side_by_side.png"), error);
  REQUIRE((left && sbs));
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x)
      for (int c = 0; c < 3; ++c)
        CHECK(left->rgb[static_cast<size_t>((y * 40 + x) * 3 + c)] ==
              sbs->rgb[static_cast<size_t>((y * 80 + x) * 3 + c)]);
}

TEST_CASE("cli cameras: the same bytes for 1 and 2 threads with every projection and stereo mode",
          "[cli][stereo][determinism]") {
  const std::pair<const char*, const char*> cameras[] = {
      {"perspective", R"("fov": 40, "stereo": {"mode": "anaglyph"})"},
      {"perspective-sbs", R"("fov": 40, "aperture": 0.05, "stereo": {"mode": "side_by_side", "swap": true})"},
      {"orthographic", R"("projection": "orthographic", "width": 4)"},
      {"fisheye", R"("projection": "fisheye", "fov": 200, "stereo": {"mode": "top_bottom"})"},
      {"equirectangular", R"("projection": "equirectangular", "stereo": {"mode": "top_bottom", "convergence": 2})"},
  };
  for (const auto& [name, camera] : cameras) {
    INFO(name);
    const std::string s = scene(std::string("threads-") + name + ".json", camera);
    const std::string a = output_path(std::string("cam-") + name + "-1.png"),
                      b = output_path(std::string("cam-") + name + "-2.png");
    REQUIRE(rtcli("render -q '" + s + "' --threads 1 -o '" + a + "'").code == 0);
    REQUIRE(rtcli("render -q '" + s + "' --threads 2 -o '" + b + "'").code == 0);
    CHECK(read_file(a) == read_file(b));
  }
}

TEST_CASE("cli cameras: stereo with an orthographic camera, or with --aa-debug, is refused", "[cli][stereo][errors]") {
  const std::string ortho = scene("ortho-stereo.json", R"("projection": "orthographic")");
  Run r = rtcli("render '" + ortho + "' --stereo anaglyph -o '" + output_path("no.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("orthographic (parallel rays see no depth)"));
  const std::string persp = scene("aa-stereo.json", R"("fov": 40)");
  r = rtcli("render '" + persp + "' --stereo anaglyph --aa-debug -o '" + output_path("no.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("does not go with --stereo"));
  r = rtcli("render '" + persp + "' --stereo sideways");
  CHECK(r.code == 2);
}

TEST_CASE("cli cameras: an animated stereo render makes an anaglyph GIF", "[cli][stereo][animation]") {
  const std::string gif = output_path("turntable-anaglyph.gif");
  const Run r =
      rtcli("render scenes/turntable.json -q --stereo anaglyph --frames 0-2 --width 48 --height 27 -o '" + gif + "'");
  REQUIRE(r.code == 0);
  CHECK(fs::file_size(gif) > 100);
}

TEST_CASE("cli cameras: stereo numbers whose eyes overflow single precision are refused at the key, in every mode",
          "[cli][stereo][errors][hostile]") {
  // Each of these killed render with SIGSEGV (issue 36) and validate called it valid: 1e-45 is a
  // denormal that passes "> 0", and each eye's view turned by an infinite amount.
  const char* cases[][3] = {
      {"anaglyph", R"("convergence": 1e-45)", "/camera/stereo/convergence"},
      {"side_by_side", R"("eye_separation": 100, "convergence": 1e-37)", "/camera/stereo/convergence"},
      {"top_bottom", R"("eye_separation": 1e38, "convergence": 0.01)", "/camera/stereo/convergence"},
      {"pair", R"("eye_separation": 1e38)", "/camera/stereo/eye_separation"},
  };
  for (const char* projection : {"perspective", "equirectangular", "fisheye"}) {
    for (const auto& c : cases) {
      INFO(projection << " " << c[0] << " " << c[1]);
      const std::string file =
          scene("stereo-overflow.json", std::string(R"("projection": ")") + projection + R"(", "stereo": {"mode": ")" +
                                            c[0] + "\", " + c[1] + "}");
      Run r = rtcli("validate '" + file + "'");
      CHECK(r.code == 2);
      CHECK_THAT(r.output,
                 Catch::Contains(c[2]) && Catch::Contains("expected eye_separation / convergence at most 20000"));
      r = rtcli("render '" + file + "' -o '" + output_path("stereo-overflow.png") + "'");
      CHECK(r.code == 2);
      CHECK_FALSE(fs::exists(output_path("stereo-overflow.png")));
    }
  }
  // Far inside the limit: renders.
  const std::string fine =
      scene("stereo-near.json", R"("stereo": {"mode": "anaglyph", "eye_separation": 1, "convergence": 0.001})");
  CHECK(rtcli("render '" + fine + "' -o '" + output_path("stereo-near.png") + "'").code == 0);
  // --stereo on a camera whose focus distance (the convergence's default) is a denormal: the eyes'
  // rays are not finite, and the traversal answers them with misses rather than a fault.
  const std::string denormal = scene("stereo-denormal.json", R"("focus_distance": 1e-45)");
  CHECK(rtcli("render '" + denormal + "' --stereo anaglyph -o '" + output_path("stereo-denormal.png") + "'").code == 0);
}
