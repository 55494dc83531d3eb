// render --environment FILE: a glTF model (or any scene) lit by an HDR image without a scene file;
// the image replaces the scene's background, and names itself in the render's provenance.
#include <string>

#include <catch2/catch.hpp>

#include "io/image/exr_file.h"
#include "io/image/png_file.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace {

double mean_level(const std::string& path) {
  std::string error;
  const auto png = rt::read_png(path, error);
  REQUIRE(png);
  double sum = 0.0;
  for (const uint8_t v : png->rgb) sum += v;
  return sum / static_cast<double>(png->rgb.size());
}

}  // namespace

TEST_CASE("cli: --environment lights a glTF model with an HDR image, no scene file needed", "[cli][environment]") {
  const std::string out = rt::test::fresh_folder("environment-option");
  const std::string model = "scenes/models/knot.glb --integrator path --spp 8 --width 64 --height 48 -q ";
  REQUIRE(rt::test::rtcli("render " + model + "-o " + out + "/plain.png").code == 0);
  REQUIRE(rt::test::rtcli("render " + model + "--environment scenes/textures/sky.hdr -o " + out + "/sky.png").code ==
          0);
  REQUIRE(
      rt::test::rtcli("render " + model +
                      "--environment scenes/textures/sky.hdr --environment-intensity 4 --environment-rotate 90 -o " +
                      out + "/bright.png")
          .code == 0);
  // Blender's dark grey world becomes the sky, seen behind the model and lighting it; 4x brighter.
  const double plain = mean_level(out + "/plain.png"), sky = mean_level(out + "/sky.png"),
               bright = mean_level(out + "/bright.png");
  CHECK(sky > plain + 20.0);
  CHECK(bright > sky + 20.0);
  // The image is an input of the render: named in an EXR's settings, hashed with the scene's files.
  REQUIRE(rt::test::rtcli("render " + model + "--environment scenes/textures/sky.hdr -o " + out + "/sky.exr").code ==
          0);
  std::string error;
  const auto exr = rt::read_exr(out + "/sky.exr", 1u << 20, error);
  REQUIRE(exr);
  CHECK_THAT(exr->attributes.at("rtcli:settings"), Catch::Contains("environment=scenes/textures/sky.hdr,"));
}

TEST_CASE("cli: --environment refusals", "[cli][environment][errors]") {
  rt::test::Run r = rt::test::rtcli_bounded("render scenes/models/knot.glb --environment missing.hdr -o /tmp/x.png");
  CHECK(r.code == 2);
  CHECK_THAT(r.output,
             Catch::Contains("missing.hdr: error: --environment: cannot read \"missing.hdr\": file not found"));
  r = rt::test::rtcli_bounded(
      "render scenes/models/knot.glb --environment scenes/textures/sky.hdr --background 1 -o /tmp/x.png");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--environment and --background both replace the scene's background"));
  r = rt::test::rtcli_bounded("render scenes/models/knot.glb --environment-intensity 2 -o /tmp/x.png");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--environment-intensity applies to --environment's image"));
  r = rt::test::rtcli_bounded("render scenes/models/knot.glb --environment scenes/textures/wood.png -o /tmp/x.png");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--environment"));
}
