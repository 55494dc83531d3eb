// The Blender add-on (tools/blender/rtcli) in Blender itself, headless: installed from its zip,
// rendering the fixture scene with the engine "RTCLI" (tests/data/blender/addon_test.py and
// cancel_test.py). Blender is an optional test tool (tools/install-deps.sh --tests installs it
// with python3-numpy); without it each case says it is skipped.
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace {

// Why the add-on cannot be tested here, or "" when Blender and its numpy are there.
std::string missing_blender() {
  if (rt::test::run_shell("command -v blender >/dev/null 2>&1").code != 0)
    return "blender is not installed (tools/install-deps.sh --tests installs it)";
  if (rt::test::run_shell("blender -b --factory-startup --python-exit-code 1 --python-expr 'import numpy' "
                          ">/dev/null 2>&1")
          .code != 0)
    return "Blender's Python has no numpy (python3-numpy)";
  return "";
}

// addon_test.py's case `name` in a fresh folder; its output and exit code.
rt::test::Run run_case(const std::string& name) {
  const std::string out = rt::test::output_path("blender-addon-" + name);
  std::filesystem::remove_all(out);
  std::filesystem::create_directories(out);
  // Its own scripts folder (the add-on installed there) and temporary folder (what the engine leaves).
  return rt::test::run_shell("cd '" + out + "' && TMPDIR='" + out + "' BLENDER_USER_SCRIPTS='" + out +
                             "/scripts' blender -b --factory-startup --python-exit-code 1 --python '" +
                             rt::test::source_path("tests/data/blender/addon_test.py") + "' -- " + name + " '" + out +
                             "' '" + RTCLI_BINARY + "' 2>&1");
}

#define SKIP_WITHOUT_BLENDER()                                       \
  if (const std::string why = missing_blender(); !why.empty()) {     \
    WARN("skipped: " << why << ": the Blender add-on is not tested"); \
    return;                                                          \
  }

}  // namespace

TEST_CASE("blender add-on: a still's passes are the pixels rtcli renders from the same export by hand",
          "[tools][blender]") {
  SKIP_WITHOUT_BLENDER();
  const rt::test::Run r = run_case("still");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("addon still: ok"));
  CHECK_THAT(r.output, Catch::Contains("Modules Installed (rtcli)"));  // from the zip
}

TEST_CASE("blender add-on: an animation renders Blender's frame range and step, each frame as rtcli's",
          "[tools][blender]") {
  SKIP_WITHOUT_BLENDER();
  const rt::test::Run r = run_case("animation");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("addon animation: ok"));
  // The material node rtcli cannot represent is named once for the three frames.
  const std::string warning = "Warning: rtcli: material \"Red\": rtcli cannot represent Noise Texture";
  const size_t first = r.output.find(warning);
  CHECK(first != std::string::npos);
  CHECK(r.output.find(warning, first + 1) == std::string::npos);
}

TEST_CASE("blender add-on: rtcli's errors and a missing rtcli reach Blender's report", "[tools][blender]") {
  SKIP_WITHOUT_BLENDER();
  const rt::test::Run r = run_case("error");
  INFO(r.output);
  // Blender ends a script whose operators reported errors with --python-exit-code's 1, even when
  // the script caught them: the case's own verdict is its last line.
  CHECK_THAT(r.output, Catch::Contains("addon error: ok"));
  CHECK_THAT(r.output, !Catch::Contains("FAILED") && !Catch::Contains("Traceback"));
  CHECK_THAT(r.output, Catch::Contains("Error: world.hdr: error: the world image"));
  CHECK_THAT(r.output, Catch::Contains("expected at most"));
}

TEST_CASE("blender add-on: a portrait frame with a unit scale and a world colour matches Cycles", "[tools][blender]") {
  SKIP_WITHOUT_BLENDER();
  const rt::test::Run r = run_case("cycles");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("addon cycles: ok"));
}

TEST_CASE("blender add-on: a world's environment image turned by a Mapping node is where Cycles shows it",
          "[tools][blender]") {
  SKIP_WITHOUT_BLENDER();
  const rt::test::Run r = run_case("environment");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("addon environment: ok"));
}

TEST_CASE("blender add-on: F12 in Blender's window renders in a job thread, exporting on the main thread",
          "[tools][blender]") {
  SKIP_WITHOUT_BLENDER();
  if (rt::test::run_shell("command -v xvfb-run >/dev/null 2>&1").code != 0) {
    WARN("skipped: xvfb-run is not installed (tools/install-deps.sh --tests installs xvfb): F12 in a window is not "
         "tested");
    return;
  }
  const rt::test::Run saved = run_case("blend");
  INFO(saved.output);
  REQUIRE(saved.code == 0);
  const std::string out = rt::test::output_path("blender-addon-blend");
  const rt::test::Run r = rt::test::run_shell(
      "cd '" + out + "' && TMPDIR='" + out + "' BLENDER_USER_SCRIPTS='" + out +
      "/scripts' timeout 300 xvfb-run -a -s '-screen 0 1280x720x24' blender --factory-startup '" + out +
      "/fixture.blend' --python '" + rt::test::source_path("tests/data/blender/ui_test.py") + "' -- '" + out + "' '" +
      RTCLI_BINARY + "' 2>&1");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("addon ui: ok"));
  CHECK(std::filesystem::file_size(out + "/blender.png") > 10000);
}

TEST_CASE("blender add-on: a cancelled render leaves no rtcli process and no files behind", "[tools][blender]") {
  SKIP_WITHOUT_BLENDER();
  const std::string out = rt::test::output_path("blender-addon-cancel");
  std::filesystem::remove_all(out);
  const rt::test::Run r = rt::test::run_shell("python3 '" + rt::test::source_path("tests/data/blender/cancel_test.py") +
                                              "' blender '" + RTCLI_BINARY + "' '" + out + "' 2>&1");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("addon cancel: ok"));
}
