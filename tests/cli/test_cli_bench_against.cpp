// rtcli bench --against: the source tree's comparisons (tools/povray/compare.py,
// tools/cycles/speed.py) run with this rtcli after the bench, the command printed to rerun; what
// cannot run is said before anything slow.
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

TEST_CASE("cli: bench --against refuses a comparison without its scene, or one it does not know, at once",
          "[cli][bench]") {
  rt::test::Run r = rt::test::rtcli("bench --scene '' --against povray");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--against povray compares --scene, which is '' (skipped)"));
  CHECK_THAT(r.output, !Catch::Contains("BVH build"));  // before the benchmark, not after it
  r = rt::test::rtcli("bench --path-scene '' --against cycles");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--against cycles compares --path-scene, which is '' (skipped)"));
  r = rt::test::rtcli("bench --against mitsuba");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--against") && Catch::Contains("mitsuba"));
}

TEST_CASE("cli: bench --against povray times a scene and its POV-Ray twin, and prints the command", "[cli][bench]") {
  if (!rt::test::installed("povray")) return;
  // One sphere under a point light, no anti-aliasing: a second with either renderer at 1920 x 1440.
  const std::string scene = rt::test::write_file(
      "against_ball.json",
      R"({"render": {"antialias": {"mode": "none"}}, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
          "materials": {"red": {"kd": [0.8, 0.1, 0.1]}}, "lights": [{"type": "point", "position": [3, 4, 5]}],
          "nodes": [{"shape": "sphere", "material": "red"}]})");
  const rt::test::Run r = rt::test::rtcli("bench scenes/models/gem.gltf --scene '" + scene +
                                          "' --path-scene '' --repeats 1 --against povray");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("against POV-Ray: python3 ") && Catch::Contains("tools/povray/compare.py") &&
                           Catch::Contains("--runs 1 --rtcli "));
  CHECK_THAT(r.output, Catch::Contains("| against_ball | ") && Catch::Contains("× |"));
  // A scene whose name starts with '-' is a path all the way down, never an option.
  const std::string dashed = rt::test::write_file("-ball.json", rt::test::read_file(scene));
  const rt::test::Run d = rt::test::rtcli("bench '" + rt::test::source_path("scenes/models/gem.gltf") +
                                              "' --scene -ball.json --path-scene '' --repeats 1 --against povray",
                                          std::filesystem::path(dashed).parent_path().string());
  INFO(d.output);
  CHECK(d.code == 0);
  CHECK_THAT(d.output, Catch::Contains("| -ball | "));
}

TEST_CASE("tools/cycles/speed.py: samples a second of rtcli and Cycles on a twin with spheres, glass and a sky",
          "[cli][bench]") {
  if (!rt::test::installed("blender")) return;
  // environment.json: a chrome, a clay and a glass ball, a satin block and an HDR sky, small; enough
  // samples that their time stands out of Cycles' start-up (about a second, give or take a fifth
  // on a busy machine: 2 and 128 samples at 32 x 32 once took less time for 128, and 4 and 512 at
  // 48 x 48 once failed in a parallel ctest run; 1024 give Cycles 1.7 s of samples).
  const rt::test::Run r = rt::test::run_shell("python3 '" + rt::test::source_path("tools/cycles/speed.py") +
                                              "' --size 48 --samples 4,1024 --runs 1 --rtcli '" + RTCLI_BINARY + "' '" +
                                              rt::test::source_path("scenes/environment.json") + "' 2>&1");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("| scene | rtcli samples/s | Cycles samples/s | ratio |"));
  CHECK_THAT(r.output, Catch::Contains("environment.json | ") && Catch::Contains("× | "));
  // A scene it cannot twin is refused by name.
  const rt::test::Run bad = rt::test::run_shell("python3 '" + rt::test::source_path("tools/cycles/speed.py") +
                                                "' --size 8 --samples 1,2 --runs 1 --rtcli '" + RTCLI_BINARY + "' '" +
                                                rt::test::source_path("scenes/csg.json") + "' 2>&1");
  CHECK(bad.code != 0);
  CHECK_THAT(bad.output, Catch::Contains("material 'floor': [") && Catch::Contains("] have no twin"));
}

TEST_CASE("tools/povray/compare.py --without-transmissive: a scene against POV-Ray without its glass", "[cli][bench]") {
  if (!rt::test::installed("povray")) return;
  // A glass ball in a group beside a red one: the group keeps the red ball, the glass goes.
  const std::string scene = rt::test::write_file(
      "against_glass.json",
      R"({"render": {"antialias": {"mode": "none"}}, "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
          "materials": {"red": {"kd": [0.8, 0.1, 0.1]}, "glass": {"kd": 0, "transmission": [0, 1, 1], "ior": 1.5}},
          "lights": [{"type": "point", "position": [3, 4, 5]}],
          "nodes": [{"children": [{"shape": "sphere", "material": "glass"},
                                  {"shape": "sphere", "material": "red", "transform": {"translate": [2, 0, 0]}}]}]})");
  const std::string compare = "python3 '" + rt::test::source_path("tools/povray/compare.py") +
                              "' --width 160 --height 120 --runs 1 --rtcli '" + RTCLI_BINARY + "' ";
  const rt::test::Run r = rt::test::run_shell(compare + "--without-transmissive '" + scene + "' 2>&1");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output,
             Catch::Contains("| against_glass (without its 1 transmissive node) | ") && Catch::Contains("× | rms "));
  // The copy without the glass is gone once compared.
  int copies_left = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(scene).parent_path()))
    copies_left += entry.path().filename().string().find("without-transmissive") != std::string::npos;
  CHECK(copies_left == 0);
  // A scene with nothing transmissive has nothing to show: refused before anything is rendered.
  const std::string matte =
      rt::test::write_file("against_matte.json",
                           R"({"materials": {"red": {"kd": 0.5}}, "nodes": [{"shape": "sphere", "material": "red"}]})");
  const rt::test::Run refused = rt::test::run_shell(compare + "--without-transmissive '" + matte + "' 2>&1");
  CHECK(refused.code != 0);
  CHECK_THAT(refused.output,
             Catch::Contains("has no node of a transmissive material to leave out") && !Catch::Contains("| scene |"));
}

TEST_CASE("tools/cycles/speed.py: the Blender fixture with one light and no bump map, to see where its time goes",
          "[cli][bench][blender]") {
  if (!rt::test::installed("blender")) return;
  // Debian's Python: one that pyenv or a venv puts first on PATH hides python3-numpy from the
  // glTF exporter that builds the fixture in Blender.
  const rt::test::Run r = rt::test::run_shell("/usr/bin/python3 '" + rt::test::source_path("tools/cycles/speed.py") +
                                              "' fixture --fixture-light Sun --fixture-bumps off --size 48 --samples "
                                              "4,1024 --runs 1 --rtcli '" +
                                              RTCLI_BINARY + "' 2>&1");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("| fixture (Sun alone, no bump map) | ") && Catch::Contains("× | "));
  const rt::test::Run bad = rt::test::run_shell("python3 '" + rt::test::source_path("tools/cycles/speed.py") +
                                                "' fixture --fixture-light Moon 2>&1");
  CHECK(bad.code != 0);
  CHECK_THAT(bad.output, Catch::Contains("invalid choice: 'Moon'"));
}
