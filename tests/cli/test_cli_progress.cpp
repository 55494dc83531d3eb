// render --progress (a bar, lines for programs such as the Blender add-on, or nothing),
// --max-depth (the bounces after the camera ray, as the scene's render.max_depth) and --time (the
// path tracer stopped between whole passes).
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "io/json/document.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

TEST_CASE("cli: --progress lines prints each whole percent once, rising to 100", "[cli][progress]") {
  const std::string out = rt::test::output_path("progress-lines.png");
  const rt::test::Run r = rt::test::rtcli(
      "render scenes/default.json --width 320 --height 240 --integrator path "
      "--spp 8 -o '" +
      out + "' --progress lines");
  INFO(r.output);
  REQUIRE(r.code == 0);
  int last = -1, lines = 0;
  for (size_t at = r.output.find("rtcli: progress "); at != std::string::npos;
       at = r.output.find("rtcli: progress ", at + 1)) {
    const int percent = std::stoi(r.output.substr(at + 16));
    CHECK(percent > last);
    last = percent;
    ++lines;
    CHECK(r.output.substr(at + 16 + std::to_string(percent).size(), 2) == "%\n");
  }
  CHECK(last == 100);
  CHECK(lines >= 2);
  CHECK(r.output.find('\r') == std::string::npos);  // no bar redrawn in place
}

TEST_CASE("cli: --progress none and a pipe print no progress, a wrong style is named", "[cli][progress]") {
  const std::string out = rt::test::output_path("progress-none.png");
  for (const std::string option : {"--progress none", "", "--progress lines --quiet"}) {
    INFO(option);
    const rt::test::Run r =
        rt::test::rtcli("render scenes/default.json --width 64 --height 48 -o '" + out + "' " + option);
    CHECK(r.code == 0);
    // Lines asked for outright are printed even with --quiet (a program asked for them).
    CHECK((r.output.find("rtcli: progress") != std::string::npos) == (option.find("lines") != std::string::npos));
  }
  const rt::test::Run bad = rt::test::rtcli_bounded("render scenes/default.json --progress percent");
  CHECK(bad.code == 2);
  CHECK_THAT(bad.output, Catch::Contains("unknown progress style \"percent\"") &&
                             Catch::Contains("expected one of: auto, bar, lines, none"));
}

TEST_CASE("cli: --max-depth replaces the scene's bounces: 0 traces no reflected ray", "[cli][progress]") {
  const std::string stats = rt::test::output_path("max-depth.json");
  const std::string out = rt::test::output_path("max-depth.png");
  const auto reflections = [&](const std::string& option) {
    const rt::test::Run r = rt::test::rtcli("render scenes/reflection.json --width 64 --height 48 -q -o '" + out +
                                            "' --stats '" + stats + "' " + option);
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string json = rt::test::read_file(stats);
    const size_t at = json.find("\"reflection\": ");
    REQUIRE(at != std::string::npos);
    CHECK_THAT(json, Catch::Contains("\"max_depth\": " + (option.empty() ? std::string("") : option.substr(12))));
    return std::stoll(json.substr(at + 14));
  };
  CHECK(reflections("") > 0);
  CHECK(reflections("--max-depth 0") == 0);
  CHECK(reflections("--max-depth 1") > 0);
  const rt::test::Run bad = rt::test::rtcli_bounded("render scenes/reflection.json --max-depth 65");
  CHECK(bad.code == 2);
  CHECK_THAT(bad.output, Catch::Contains("--max-depth: expected a whole number from 0 to 64, found 65"));
}

TEST_CASE("cli: --time stops the path tracer after whole passes, with time enough the same bytes",
          "[cli][progressive]") {
  const std::string dir = rt::test::fresh_folder("cli-time");
  const std::string base = "render scenes/cornell_box.json --width 48 --height 48 --spp 24 -q";
  REQUIRE(rt::test::rtcli(base + " -o '" + dir + "/all.png'").code == 0);
  auto r = rt::test::rtcli("render scenes/cornell_box.json --width 48 --height 48 --spp 24 --time 600 -o '" + dir +
                           "/timed.png'");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("--time 600 s: finished after 3 passes of 8 samples: 24 samples per pixel"));
  CHECK(rt::test::read_file(dir + "/timed.png") == rt::test::read_file(dir + "/all.png"));
  // A limit far below one pass: the first pass still completes, a whole image of 8 samples.
  r = rt::test::rtcli("render scenes/cornell_box.json --width 48 --height 48 --spp 4096 --time 0.001 -o '" + dir +
                      "/quick.png'");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("stopped after 1 pass of 8 samples: 8 samples per pixel"));
  r = rt::test::rtcli("render scenes/cornell_box.json --width 48 --height 48 --spp 4096 --time 0.001 -q --stats '" +
                      dir + "/s.json' -o '" + dir + "/quick2.png'");
  REQUIRE(r.code == 0);
  const auto stats = rt::Json::parse(rt::test::read_file(dir + "/s.json"));
  CHECK(stats["path"]["time"]["passes"] == 1);
  CHECK(stats["path"]["time"]["stopped"] == true);
  CHECK(stats["path"]["mean_samples_per_pixel"] == 8.0);
  // Whitted renders each pixel once: refused, nothing written.
  r = rt::test::rtcli("render scenes/soft_shadows.json --time 2 -o '" + dir + "/w.png'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--time stops the path tracer between passes"));
  CHECK_FALSE(std::filesystem::exists(dir + "/w.png"));
}
