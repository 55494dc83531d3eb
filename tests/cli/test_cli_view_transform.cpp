// render --view-transform: PNG output through an OpenColorIO view (io/image/view_transform.h), with
// a config the test writes (a view that halves, a look that doubles: exact bytes expected), and
// Blender's own config where Blender is installed; every mistake exits 2 with its reason.
#include <string>

#include <catch2/catch.hpp>

#include "io/image/png_file.h"
#include "io/image/view_transform.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace {

const char* kHalfConfig = R"(ocio_profile_version: 1
search_path: ""
roles:
  default: linear
  scene_linear: linear
displays:
  sRGB:
    - !<View> {name: Half, colorspace: half}
active_displays: [sRGB]
active_views: [Half]
looks:
  - !<Look>
    name: Double
    process_space: linear
    transform: !<MatrixTransform> {matrix: [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]}
colorspaces:
  - !<ColorSpace>
    name: linear
    bitdepth: 32f
  - !<ColorSpace>
    name: half
    bitdepth: 32f
    from_reference: !<MatrixTransform> {matrix: [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1]}
)";

// The first pixel of a PNG.
std::vector<int> first_pixel(const std::string& path) {
  std::string error;
  const auto png = rt::read_png(path, error);
  REQUIRE(png);
  return {png->rgb[0], png->rgb[1], png->rgb[2]};
}

double mean_difference(const std::string& a, const std::string& b) {
  std::string error;
  const auto x = rt::read_png(a, error), y = rt::read_png(b, error);
  REQUIRE(x);
  REQUIRE(y);
  double sum = 0.0;
  for (size_t i = 0; i < x->rgb.size(); ++i) sum += std::abs(int(x->rgb[i]) - int(y->rgb[i]));
  return sum / double(x->rgb.size());
}

}  // namespace

TEST_CASE("cli: --view-transform puts PNG output through an OpenColorIO view and look", "[cli][view]") {
  const std::string dir = rt::test::fresh_folder("view-transform");
  const std::string config = rt::test::write_file("view-transform/half.ocio", kHalfConfig);
  const std::string scene = rt::test::write_file(
      "view-transform/sky.json",
      R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "background": [0.8, 0.4, 0.2], "nodes": []})");
  const std::string base = "render " + scene + " --width 4 --height 4 -q --ocio-config " + config;
  // The view halves the radiance and its output is the display's: no sRGB curve on top.
  REQUIRE(rt::test::rtcli(base + " --view-transform half -o " + dir + "/half.png").code == 0);
  CHECK(first_pixel(dir + "/half.png") == std::vector<int>{102, 51, 26});  // 0.4, 0.2, 0.1 x 255
  REQUIRE(rt::test::rtcli(base + " --view-transform Half --look double -o " + dir + "/look.png").code == 0);
  CHECK(first_pixel(dir + "/look.png") == std::vector<int>{204, 102, 51});
  // Exposure comes first: one stop up doubles what the view receives.
  REQUIRE(rt::test::rtcli(base + " --view-transform Half --exposure 1 -o " + dir + "/exposed.png").code == 0);
  CHECK(first_pixel(dir + "/exposed.png") == std::vector<int>{204, 102, 51});

  SECTION("mistakes exit 2 and say why") {
    const auto wrong_view = rt::test::rtcli(base + " --view-transform Filmic -o " + dir + "/x.png");
    CHECK(wrong_view.code == 2);
    CHECK_THAT(wrong_view.output, Catch::Contains("expected a view of the config's display \"sRGB\" (\"Half\")"));
    const auto wrong_look = rt::test::rtcli(base + " --view-transform half --look punchy -o " + dir + "/x.png");
    CHECK(wrong_look.code == 2);
    CHECK_THAT(wrong_look.output, Catch::Contains("looks (\"Double\"), found \"punchy\""));
    const auto alone = rt::test::rtcli("render " + scene + " --look double -o " + dir + "/x.png");
    CHECK(alone.code == 2);
    CHECK_THAT(alone.output, Catch::Contains("--look goes with --view-transform"));
    const auto both = rt::test::rtcli(base + " --view-transform half --tone-map filmic -o " + dir + "/x.png");
    CHECK(both.code == 2);
    CHECK_THAT(both.output, Catch::Contains("does not go with --tone-map"));
    const std::string junk = rt::test::write_file("view-transform/junk.ocio", "ocio_profile_version: [\n\"");
    const auto bad =
        rt::test::rtcli("render " + scene + " --view-transform half --ocio-config " + junk + " -o " + dir + "/x.png");
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("not a usable OpenColorIO config"));
    const auto fifo_made = rt::test::run_shell("mkfifo " + dir + "/fifo.ocio");
    REQUIRE(fifo_made.code == 0);
    const auto fifo = rt::test::rtcli_bounded("render " + scene + " --view-transform half --ocio-config " + dir +
                                              "/fifo.ocio -o " + dir + "/x.png");
    CHECK(fifo.code == 2);
    CHECK_THAT(fifo.output, Catch::Contains("not a regular file"));
    const auto missing = rt::test::rtcli("render " + scene + " --view-transform half --ocio-config " + dir +
                                         "/none.ocio -o " + dir + "/x.png");
    CHECK(missing.code == 2);
  }
}

TEST_CASE("cli: Blender's own config: Standard is rtcli's sRGB encoding, Filmic is not", "[cli][view]") {
  if (rt::ViewTransform::blender_config().empty()) {
    WARN("skipped: no Blender colour-management config installed (" << rt::kBlenderConfigs[0] << ")");
    return;
  }
  const std::string dir = rt::test::fresh_folder("view-transform-blender");
  const std::string base = "render scenes/material_extensions.json --width 48 --height 30 --spp 4 -q -o " + dir;
  REQUIRE(rt::test::rtcli(base + "/plain.png").code == 0);
  REQUIRE(rt::test::rtcli(base + "/standard.png --view-transform standard").code == 0);
  REQUIRE(rt::test::rtcli(base + "/filmic.png --view-transform filmic").code == 0);
  CHECK(mean_difference(dir + "/plain.png", dir + "/standard.png") < 0.5);  // the LUT's rounding at most
  CHECK(mean_difference(dir + "/plain.png", dir + "/filmic.png") > 5.0);
}
