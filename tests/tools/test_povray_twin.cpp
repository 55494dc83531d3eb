// tools/povray/twin.py: the POV-Ray twins that docs/benchmark.md times rtcli against. Each shipped
// scene it claims converts completely; anything it cannot convert is refused by name, never
// silently dropped.
#include <catch2/catch.hpp>

#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace {

rt::test::Run twin(const std::string& scene, const std::string& out) {
  return rt::test::run_shell("python3 '" + rt::test::source_path("tools/povray/twin.py") + "' '" +
                             rt::test::source_path(scene) + "' '" + out + "' --width 1920 --height 1440 2>&1");
}

}  // namespace

TEST_CASE("povray twin: the benchmark scenes convert, with the camera, lights and sampling they ask", "[tools]") {
  for (const char* scene : {"scenes/reflection.json", "scenes/refraction.json", "scenes/soft_shadows.json",
                            "scenes/antialias.json", "scenes/csg.json"}) {
    INFO(scene);
    const std::string out = rt::test::output_path("twin.pov");
    const rt::test::Run r = twin(scene, out);
    REQUIRE(r.code == 0);
    CHECK_THAT(r.output, Catch::Contains("+W1920 +H1440") && Catch::Contains("File_Gamma=sRGB"));
    const std::string pov = rt::test::read_file(out);
    CHECK_THAT(pov, Catch::Contains("right -x*1.33333333") && Catch::Contains("assumed_gamma 1.0"));
    CHECK_THAT(pov, Catch::Contains("light_source"));
  }
  // soft_shadows: 16 samples become a jittered 4 x 4 area light; refraction: glass reflecting from
  // 0 (head on) to 1 (grazing) by Fresnel, as rtcli's, not only by total internal reflection.
  twin("scenes/soft_shadows.json", rt::test::output_path("soft.pov"));
  CHECK_THAT(rt::test::read_file(rt::test::output_path("soft.pov")), Catch::Contains(", 4, 4 jitter"));
  twin("scenes/refraction.json", rt::test::output_path("glass.pov"));
  CHECK_THAT(rt::test::read_file(rt::test::output_path("glass.pov")),
             Catch::Contains("reflection { rgb <0, 0, 0>, rgb <1, 1, 1> fresnel on }") && Catch::Contains("ior 1.33") &&
                 Catch::Contains("fade_power 1001"));
  // csg: POV-Ray's own four operations, an operand's material kept (the die's pips), the solid's
  // material on operands without one, coloured glass as a filter, a texture on a plane.
  twin("scenes/csg.json", rt::test::output_path("csg.pov"));
  const std::string csg = rt::test::read_file(rt::test::output_path("csg.pov"));
  for (const char* op : {"union {", "merge {", "intersection {", "difference {"}) CHECK_THAT(csg, Catch::Contains(op));
  CHECK_THAT(csg, Catch::Contains("rgbf <1, 0.8, 0.45, 1>") && Catch::Contains("gamma srgb") &&
                      Catch::Contains("textures/checker.png") &&
                      Catch::Contains("matrix <0.4, 0, 0, 0, 0, -0.8, 0, 1, 0, -1, 0, -1>"));
}

TEST_CASE("povray twin: what has no twin is refused by name", "[tools]") {
  rt::test::Run r = twin("scenes/primitives.json", rt::test::output_path("no.pov"));
  CHECK(r.code != 0);
  CHECK_THAT(r.output, Catch::Contains("only analytic shapes, groups and CSG have twins"));
  r = twin("scenes/textures.json", rt::test::output_path("no.pov"));
  CHECK(r.code != 0);
  CHECK_THAT(r.output, Catch::Contains("have no twin"));
  // A texture has a twin on a plane only (POV-Ray's image_map is placed by the plane's own (u, v)).
  const std::string textured_ball = rt::test::write_file(
      "twin_textured_ball.json",
      R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "materials": {"m": {"texture": "checker.png"}},
          "nodes": [{"shape": "sphere", "material": "m"}]})");
  r = rt::test::run_shell("python3 '" + rt::test::source_path("tools/povray/twin.py") + "' '" + textured_ball + "' '" +
                          rt::test::output_path("no.pov") + "' 2>&1");
  CHECK(r.code != 0);
  CHECK_THAT(r.output, Catch::Contains("a texture on a sphere has no twin (only on a plane)"));
}
