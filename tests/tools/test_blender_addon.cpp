// The Blender add-on (tools/blender/rtcli) in Blender itself, headless: installed from its zip,
// rendering the fixture scene with the engine "RTCLI" (tests/data/blender/addon_test.py and
// cancel_test.py). Blender is an optional test tool (tools/install-deps.sh --tests installs it
// with python3-numpy); without it each case says it is skipped.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "io/image/exr_file.h"
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

// The environment Blender runs in for a test's folder `out`: its own scripts folder (the add-on
// installed there), preferences and temporary folder (what the engine leaves), nothing of the user's.
std::string blender_env(const std::string& out) {
  return "cd '" + out + "' && TMPDIR='" + out + "' BLENDER_USER_SCRIPTS='" + out + "/scripts' BLENDER_USER_CONFIG='" +
         out + "/config' ";
}

// addon_test.py's case `name` in a fresh folder (blender-addon-FOLDER, default the case's name).
rt::test::Run run_case(const std::string& name, const std::string& folder = "") {
  const std::string out = rt::test::output_path("blender-addon-" + (folder.empty() ? name : folder));
  std::filesystem::remove_all(out);
  std::filesystem::create_directories(out + "/config");
  return rt::test::run_shell(blender_env(out) + "blender -b --factory-startup --python-exit-code 1 --python '" +
                             rt::test::source_path("tests/data/blender/addon_test.py") + "' -- " + name + " '" + out +
                             "' '" + RTCLI_BINARY + "' 2>&1");
}

// Channel `name` of an EXR's colour layer.
std::vector<float> channel(const rt::ExrImage& image, const std::string& name) {
  const rt::ExrLayer* colour = image.layer("");
  REQUIRE(colour);
  const auto at = std::find(colour->channels.begin(), colour->channels.end(), name);
  REQUIRE(at != colour->channels.end());
  const size_t c = static_cast<size_t>(at - colour->channels.begin()), n = colour->channels.size();
  std::vector<float> out;
  for (size_t i = c; i < colour->values.size(); i += n) out.push_back(colour->values[i]);
  return out;
}

#define SKIP_WITHOUT_BLENDER()                                        \
  if (const std::string why = missing_blender(); !why.empty()) {      \
    WARN("skipped: " << why << ": the Blender add-on is not tested"); \
    return;                                                           \
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
    WARN(
        "skipped: xvfb-run is not installed (tools/install-deps.sh --tests installs xvfb): F12 in a window is not "
        "tested");
    return;
  }
  const rt::test::Run saved = run_case("blend", "window");
  INFO(saved.output);
  REQUIRE(saved.code == 0);
  const std::string out = rt::test::output_path("blender-addon-window");
  const rt::test::Run r = rt::test::run_shell(
      blender_env(out) + "timeout 300 xvfb-run -a -s '-screen 0 1280x720x24' blender --factory-startup '" + out +
      "/fixture.blend' --python '" + rt::test::source_path("tests/data/blender/ui_test.py") + "' -- '" + out + "' '" +
      RTCLI_BINARY + "' 2>&1");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("addon ui: ok"));
  CHECK(std::filesystem::file_size(out + "/blender.png") > 10000);
}

TEST_CASE("blender add-on: blender -b FILE.blend -E RTCLI -a renders each frame of the range, rtcli found on PATH",
          "[tools][blender]") {
  SKIP_WITHOUT_BLENDER();
  const rt::test::Run saved = run_case("blend", "command-line");
  INFO(saved.output);
  REQUIRE(saved.code == 0);
  const std::string out = rt::test::output_path("blender-addon-command-line");
  const std::string bin = std::filesystem::path(RTCLI_BINARY).parent_path().string();
  // The preferences are not read (--factory-startup): no executable set, so rtcli comes from PATH.
  const rt::test::Run r = rt::test::run_shell(
      blender_env(out) + "PATH='" + bin + "':\"$PATH\" blender -b --factory-startup --addons rtcli '" + out +
      "/fixture.blend' --python-expr \"import bpy; s = bpy.context.scene; s.render.resolution_percentage = 25; "
      "s.render.image_settings.file_format = 'OPEN_EXR'\" -E RTCLI -o '" +
      out + "/cli_####' -s 1 -e 3 -j 2 -a 2>&1");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_FALSE(std::filesystem::exists(out + "/cli_0002.exr"));  // the step
  for (const int frame : {1, 3}) {
    INFO("frame " << frame);
    const std::string hand = out + "/hand-" + std::to_string(frame) + ".exr";
    const rt::test::Run direct =
        rt::test::rtcli("render '" + out +
                        "/hand/scene.glb' --integrator path --spp 32 --max-depth 12 --camera Camera --width 160 "
                        "--height 90 --fps 24 --exr-float -q --frame " +
                        std::to_string(frame) + " -o '" + hand + "'");
    REQUIRE(direct.code == 0);
    char name[32];
    std::snprintf(name, sizeof name, "/cli_%04d.exr", frame);
    std::string error;
    const auto blender = rt::read_exr(out + name, 1 << 20, error);
    const auto rtcli = rt::read_exr(hand, 1 << 20, error);
    INFO(error);
    REQUIRE(blender);
    REQUIRE(rtcli);
    CHECK(blender->width == 160);
    for (const char* c : {"R", "G", "B"}) CHECK(channel(*blender, c) == channel(*rtcli, c));
    const std::vector<float> alpha = channel(*blender, "A");
    CHECK(std::all_of(alpha.begin(), alpha.end(), [](float a) { return a == 1.0f; }));
  }
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
