// The rtcli binary against hostile and careless input: special files, huge sizes, an output that
// is the input, a far-away object, Ctrl-C in the middle of a render. Each gets a clear message
// and exit code 2 (or renders, where the input is valid), quickly, and leaves no file behind.
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <catch2/catch.hpp>

#include "io/json/document.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;
using rt::test::output_path;
using rt::test::read_file;
using rt::test::rtcli;
using rt::test::Run;
using rt::test::write_file;

namespace {

bool has_temporary_files(const std::string& folder) {
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().filename().string().rfind(".rtcli-", 0) == 0) return true;
  return false;
}

}  // namespace

TEST_CASE("cli: special files are refused, not read forever", "[cli][errors][hostile]") {
  const std::string fifo = output_path("fifo.json");
  fs::remove(fifo);
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  Run r = rt::test::rtcli_bounded("render '" + fifo + "' -o '" + output_path("fifo.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("fifo.json: error: is a named pipe (FIFO), not a regular file"));
  r = rt::test::rtcli_bounded("render /dev/zero -o '" + output_path("zero.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("/dev/zero: error: is a character device, not a regular file"));
  // The same through a mesh reference and as a glTF model.
  const std::string scene = write_file("fifo-mesh.json", R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
    "nodes": [{"mesh": {"file": "fifo.json"}}, {"mesh": {"file": "/dev/zero"}}]})");
  r = rt::test::rtcli_bounded("validate '" + scene + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("/nodes/0/mesh/file") && Catch::Contains("named pipe") &&
                           Catch::Contains("/nodes/1/mesh/file") && Catch::Contains("character device"));
  const std::string glb = output_path("fifo.glb");
  fs::remove(glb);
  REQUIRE(::mkfifo(glb.c_str(), 0600) == 0);
  r = rt::test::rtcli_bounded("render '" + glb + "' -o '" + output_path("fifo-glb.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("named pipe"));
}

TEST_CASE("cli: a symbolic link loop says what it is", "[cli][errors][hostile]") {
  const std::string a = output_path("loop-a.json"), b = output_path("loop-b.json");
  fs::remove(a);
  fs::remove(b);
  fs::create_symlink(b, a);
  fs::create_symlink(a, b);
  const Run r = rt::test::rtcli_bounded("render '" + a + "' -o '" + output_path("loop.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("loop-a.json: error: is a loop of symbolic links"));
}

TEST_CASE("cli: the output may not be the input, even through a link", "[cli][errors][hostile]") {
  const std::string scene = read_file(rt::test::source_path("scenes/default.json"));
  const std::string input = write_file("scene-named.png", scene);
  Run r = rtcli("render '" + input + "' -o '" + input + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("it is the input file"));
  const std::string link = output_path("link-to-scene.png");
  fs::remove(link);
  fs::create_symlink(input, link);
  r = rtcli("render '" + input + "' -o '" + link + "'");
  CHECK(r.code == 2);
  CHECK(read_file(input) == scene);  // untouched
}

TEST_CASE("cli: sizes beyond the limits are refused with the limit", "[cli][errors][hostile]") {
  Run r = rtcli("render scenes/default.json --width 16384 --height 16384 -o '" + output_path("huge.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("268435456 pixels, more than the 67108864"));
  r = rtcli("render scenes/default.json --width 100000 -o '" + output_path("huge.png") + "'");
  CHECK(r.code == 2);
  const std::string scene = write_file("deep-max-depth.json", R"({"render": {"max_depth": 1000000000},
    "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "nodes": []})");
  r = rtcli("render '" + scene + "' -o '" + output_path("depth.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("/render/max_depth: expected an integer in [0, 64]"));
  CHECK_FALSE(fs::exists(output_path("huge.png")));
}

TEST_CASE("cli: a sphere 2e38 away beside two cubes renders", "[cli][hostile]") {
  const std::string scene = write_file("far-sphere.json", R"({
    "camera": {"position": [0, 0, 8], "look_at": [0, 0, 0]},
    "materials": {"m": {}}, "lights": [{"type": "point", "position": [0, 5, 5]}],
    "nodes": [{"shape": "sphere", "material": "m", "transform": {"translate": [2e38, 0, 0]}},
              {"shape": "cube", "material": "m"}, {"shape": "cube", "material": "m", "transform": {"translate": [3, 0, 0]}}]})");
  const Run r =
      rt::test::rtcli_bounded("render '" + scene + "' --width 40 --height 30 -o '" + output_path("far.png") + "'");
  CHECK(r.code == 0);
  const std::string beyond =
      write_file("beyond-float.json", R"({"camera": {"position": [0, 0, 8], "look_at": [0, 0, 0]},
    "materials": {"m": {}}, "nodes": [{"shape": "sphere", "material": "m", "transform": {"translate": [3e38, 0, 0], "scale": 1e38}}]})");
  const Run b = rt::test::rtcli_bounded("render '" + beyond + "' -o '" + output_path("beyond.png") + "'");
  CHECK(b.code == 2);
  CHECK_THAT(b.output, Catch::Contains("/nodes/0: expected a shape within the single-precision range"));
}

TEST_CASE("cli: Ctrl-C stops a render within a second and writes nothing", "[cli][hostile]") {
  fs::create_directories(output_path("interrupted"));
  const std::string out = output_path("interrupted/long.png");
  fs::remove(out);
  // About a minute of work on one thread (far more under a sanitizer).
  const auto [r, delay, seconds] =
      rt::test::interrupt_render("scenes/primitives.json", "--threads 1 --width 4000 --height 3000", out, 1.5);
  INFO("signal after " << delay << " s, exit after " << seconds << " s; output:\n" << r.output);
  CHECK(r.code == 130);
  CHECK_THAT(r.output, Catch::Contains("interrupted after") && Catch::Contains("nothing written"));
  // Stopped within a second of the signal; the margin is for a loaded 2-core CI machine.
  CHECK(seconds < delay + rt::test::kStopMargin);
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(has_temporary_files(output_path("interrupted")));
}

TEST_CASE("cli: validate reports every problem in every file, as text or JSON", "[cli][validate]") {
  Run r = rtcli("validate scenes/default.json scenes/primitives.json scenes/models/knot.glb");
  CHECK(r.code == 0);
  CHECK_THAT(r.output,
             Catch::Contains("scenes/default.json: valid") && Catch::Contains("scenes/models/knot.glb: valid"));

  r = rtcli(
      "validate tests/data/bad/type-fov-string.json tests/data/bad/ref-undefined-material.json scenes/default.json");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("tests/data/bad/type-fov-string.json:") &&
                           Catch::Contains(": error: /camera/fov: expected a number in (0, 180)") &&
                           Catch::Contains("error: /nodes/0/material:") &&
                           Catch::Contains("scenes/default.json: valid"));

  r = rtcli("validate --json tests/data/bad/unknown-key-material.json tests/data/bad/file-mesh-missing.json");
  CHECK(r.code == 2);
  const rt::Json list = rt::Json::parse(r.output);
  REQUIRE(list.is_array());
  REQUIRE(list.size() == 2);
  CHECK(list[0]["file"] == "tests/data/bad/unknown-key-material.json");
  CHECK(list[0]["pointer"] == "/materials/red/shinyness");
  CHECK(list[0]["severity"] == "error");
  CHECK(list[0]["line"].is_number());
  CHECK(list[0]["column"].is_number());
  CHECK(list[1]["pointer"] == "/nodes/1/mesh/file");
  CHECK_THAT(list[1]["message"].get<std::string>(), Catch::Contains("file not found"));

  r = rtcli("validate");
  CHECK(r.code == 2);
}

TEST_CASE("cli: a problem inside a glTF file names its pointer and line:column, in text and JSON",
          "[cli][validate][gltf]") {
  // Through a scene: reported at the scene's reference, with the place inside the glTF file.
  Run r = rtcli("validate tests/data/bad/file-mesh-accessor-overrun.json");
  CHECK(r.code == 2);
  CHECK_THAT(r.output,
             Catch::Contains("file-mesh-accessor-overrun.json:48:17: error: /nodes/1/mesh/file: ") &&
                 Catch::Contains("  in tests/data/bad/models/accessor-overrun.gltf:1:210: /accessors/0/count"));
  r = rtcli("validate --json tests/data/bad/file-mesh-accessor-overrun.json");
  rt::Json list = rt::Json::parse(r.output);
  REQUIRE(list.size() == 1);
  CHECK(list[0]["inside"]["file"] == "tests/data/bad/models/accessor-overrun.gltf");
  CHECK(list[0]["inside"]["pointer"] == "/accessors/0/count");
  CHECK(list[0]["inside"]["line"] == 1);
  CHECK(list[0]["inside"]["column"] == 210);

  // On its own: the glTF file is the place.
  r = rtcli("validate --json tests/data/bad/models/two-parents.gltf");
  CHECK(r.code == 2);
  list = rt::Json::parse(r.output);
  REQUIRE(list.size() == 1);
  CHECK(list[0]["file"] == "tests/data/bad/models/two-parents.gltf");
  CHECK(list[0]["pointer"] == "/nodes/1/children/0");
  CHECK(list[0]["line"] == 1);
  CHECK(list[0]["column"] == 105);
  CHECK_FALSE(list[0].contains("inside"));

  // A warning travels the same way: in --json, and not at all under render's --quiet.
  const std::string gltf = write_file("sparkles.gltf", R"({"asset": {"version": "2.0"},
  "extensionsUsed": ["EXT_fancy_sparkles"],
  "scenes": [{"nodes": []}]})");
  r = rtcli("validate --json '" + gltf + "'");
  CHECK(r.code == 0);
  list = rt::Json::parse(r.output);
  const auto used =
      std::find_if(list.begin(), list.end(), [](const rt::Json& d) { return d["pointer"] == "/extensionsUsed/0"; });
  REQUIRE(used != list.end());
  CHECK((*used)["severity"] == "warning");
  CHECK((*used)["line"] == 2);
  CHECK((*used)["column"] == 22);
  r = rtcli("render -q '" + gltf + "' -o '" + output_path("sparkles.png") + "'");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("sparkles.gltf:2:22: warning: /extensionsUsed/0:"));
}
