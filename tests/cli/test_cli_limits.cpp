// The rtcli binary against issue 17's hostile cases that only the whole program shows: numbers on
// the command line, the output file (its temporary name, links, long names), Ctrl-C while a huge
// film is made, many copies in one place, a model's files outside its folder, a model that draws
// nothing. Each gets a clear message and the right exit code, quickly.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "io/base/atomic_file.h"
#include "io/json/document.h"
#include "tests/support/gltf_files.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;
using rt::test::output_path;
using rt::test::read_file;
using rt::test::rtcli;
using rt::test::Run;
using rt::test::write_file;

namespace {

Run rtcli_bounded(const std::string& args) { return rtcli(args, RTCLI_SOURCE_DIR, "timeout 20"); }

// A triangle (with UVs) in a glTF file of its own folder, its material's base colour from `image`.
std::string triangle_model(const std::string& folder, const rt::Json& image) {
  std::string buffer;
  rt::test::append<float>(buffer, {-1, -1, 0, 1, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0.5f, 1});
  rt::Json doc = {
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"material", 0}}}}}}},
      {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
      {"textures", {{{"source", 0}}}},
      {"images", {image}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 60}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 0}, {"byteOffset", 36}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}}};
  fs::create_directories(output_path(folder));
  return rt::test::write_gltf(folder + "/model.gltf", buffer, doc);
}

}  // namespace

TEST_CASE("cli limits: numbers on the command line say what they expected", "[cli][errors][limits]") {
  const std::string out = "-o '" + output_path("numbers.png") + "'";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--aa-threshold nan", "--aa-threshold: expected a number from 0 to 1, found nan, which is not finite"},
      {"--aa-threshold 0.5x", "--aa-threshold: expected a number from 0 to 1, found \"0.5x\", which is not a number"},
      {"--seed 18446744073709551616",
       "--seed: expected a whole number from 0 to 18446744073709551615, found 18446744073709551616"},
      {"--seed -1", "--seed: expected a whole number from 0 to 18446744073709551615, found -1"},
      {"--width 1e3",
       "--width: expected a whole number from 1 to 16384, found \"1e3\", which is not a whole number in decimal "
       "digits"},
      {"--width 20000", "--width: expected a whole number from 1 to 16384, found 20000"},
      {"--threads 1.5", "--threads: expected a whole number from 1 to 1024, found \"1.5\""},
  };
  for (const auto& [args, message] : cases) {
    INFO(args);
    const Run r = rtcli("render scenes/default.json " + out + " " + args);
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains(message));
  }
  CHECK(rtcli("render scenes/default.json -q --width 8 --height 8 --seed 18446744073709551615 " + out).code == 0);
}

TEST_CASE("cli limits: the temporary file is new, never a link planted under its name", "[cli][io][limits]") {
  fs::create_directories(output_path("planted"));
  const std::string victim = write_file("planted/victim.txt", "precious");
  const std::string target = output_path("planted/out.png");
  // Every name this process would try first is a link to the victim.
  for (int n = 0; n < 3; ++n) {
    const std::string link =
        output_path("planted/.rtcli-" + std::to_string(::getpid()) + "-" + std::to_string(n) + ".tmp");
    fs::remove(link);
    fs::create_symlink(victim, link);
  }
  std::string error;
  REQUIRE(rt::write_file_atomically(target, {1, 2, 3}, error));
  CHECK(read_file(victim) == "precious");
  CHECK(read_file(target) == std::string("\x01\x02\x03"));
  CHECK(fs::is_symlink(output_path("planted/.rtcli-" + std::to_string(::getpid()) + "-0.tmp")));
  CHECK((fs::status(target).permissions() & fs::perms::others_write) == fs::perms::none);  // umask applies
}

TEST_CASE("cli limits: a long output name works, one too long is refused before rendering", "[cli][errors][limits]") {
  const std::string longest = output_path(std::string(251, 'n') + ".png");  // 255 bytes: the most ext4 allows
  Run r = rtcli_bounded("render scenes/default.json -q --width 8 --height 8 -o '" + longest + "'");
  CHECK(r.code == 0);
  CHECK(fs::exists(longest));
  fs::remove(longest);
  const auto start = std::chrono::steady_clock::now();
  r = rtcli_bounded("render scenes/primitives.json --width 4000 --height 3000 -o '" +
                    output_path(std::string(252, 'n') + ".png") + "'");
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5.0);
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("its name is 256 bytes, more than the 255 the file system allows"));
  r = rtcli_bounded("render scenes/turntable.json --frames 0-1 -o '" + output_path(std::string(248, 'f') + "_##.png") +
                    "'");
  CHECK(r.code == 0);  // the frame numbers keep to the pattern's width
}

TEST_CASE("cli limits: Ctrl-C while an 8192 x 8192 film is made stops within a second", "[cli][hostile][limits]") {
  const std::string out = output_path("huge-film.png");
  fs::remove(out);
  // The signal comes when the gigabyte film is being made or the render has just begun.
  const auto [r, delay, seconds] =
      rt::test::interrupt_render("scenes/default.json", "--width 8192 --height 8192", out, 0.3);
  INFO("signal after " << delay << " s, exit after " << seconds << " s; output:\n" << r.output);
  CHECK(r.code == 130);
  CHECK_THAT(r.output, Catch::Contains("interrupted after") && Catch::Contains("nothing written"));
  // A second after the signal, and a loaded machine's margin (kStopMargin: more under
  // ThreadSanitizer, which takes up to 2.1 s to free the gigabyte film as the process ends).
  CHECK(seconds < delay + rt::test::kStopMargin);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("cli limits: a model too large to frame in single precision is refused, in render and validate",
          "[cli][errors][limits]") {
  std::string buffer;
  rt::test::append<float>(buffer, {-1.5e38f, 0, 0, 1.5e38f, 0, 0, 0, 1, 0});  // finite edges, the camera not
  const rt::Json doc = {{"scenes", {{{"nodes", {0}}}}},
                        {"nodes", {{{"mesh", 0}}}},
                        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                        {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}}};
  const std::string model = rt::test::write_gltf("huge.gltf", buffer, doc);
  for (const std::string& command :
       {"validate '" + model + "'", "render '" + model + "' -q -o '" + output_path("huge.png") + "'"}) {
    const Run r = rtcli_bounded(command);
    INFO(command);
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("huge.gltf: error: expected a model small enough to frame in single "
                                         "precision, found one whose extent (from -1.5e+38 to 1.5e+38 in x) puts "
                                         "the camera at infinity"));
  }
  CHECK_FALSE(fs::exists(output_path("huge.png")));
}

TEST_CASE("cli limits: many copies in one spot are a warning, in render and validate", "[cli][limits]") {
  std::string buffer;
  rt::test::append<float>(buffer, {-1, -1, 0, 1, -1, 0, 0, 1, 0});
  const rt::Json doc = {
      {"extensionsUsed", {"EXT_mesh_gpu_instancing"}},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", 1}}}}}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"componentType", 5126}, {"count", 1000}, {"type", "VEC3"}}}}};  // 1000 zero translations
  const std::string model = rt::test::write_gltf("stacked.gltf", buffer, doc);
  for (const std::string& command :
       {"validate '" + model + "'",
        "render '" + model + "' -q --width 16 --height 12 -o '" + output_path("stacked.png") + "'"}) {
    const Run r = rtcli_bounded(command);
    INFO(command);
    CHECK(r.code == 0);
    CHECK_THAT(r.output, Catch::Contains("warning: 1000 copies of a mesh are placed at exactly the same spot") &&
                             Catch::Contains("every ray that reaches them tests all 1000"));
  }
}

TEST_CASE("cli limits: a glTF file's images and buffers stay in its folder unless allowed", "[cli][errors][limits]") {
  write_file("secret.png", read_file(rt::test::source_path("tests/data/images/rgb8.png")));
  const std::string model = triangle_model("downloaded", {{"uri", "../secret.png"}});
  Run r = rtcli_bounded("validate '" + model + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output,
             Catch::Contains("material 0 baseColorTexture: \"../secret.png\" is outside the model's folder") &&
                 Catch::Contains("--allow-outside-files reads it"));
  r = rtcli_bounded("validate --allow-outside-files '" + model + "'");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, !Catch::Contains("warning"));
  r = rtcli_bounded("render --allow-outside-files -q --width 8 --height 8 '" + model + "' -o '" +
                    output_path("outside.png") + "'");
  CHECK(r.code == 0);
  // An absolute path, and a link inside the folder to a file outside it.
  r = rtcli_bounded("validate '" + triangle_model("absolute", {{"uri", output_path("secret.png")}}) + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("secret.png\" is outside the model's folder"));
  fs::remove(output_path("linked/secret-link.png"));
  const std::string linked = triangle_model("linked", {{"uri", "secret-link.png"}});
  fs::create_symlink(output_path("secret.png"), output_path("linked/secret-link.png"));
  r = rtcli_bounded("validate '" + linked + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("\"secret-link.png\" is outside the model's folder"));
}

TEST_CASE("cli limits: a glTF image in another format is a warning naming it once", "[cli][limits]") {
  const std::string model = triangle_model("gif-image", {{"uri", "image.gif"}});
  write_file("gif-image/image.gif", read_file(rt::test::source_path("tests/data/images/image.gif")));
  const Run r = rtcli_bounded("validate '" + model + "'");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains(
                           "material 0 baseColorTexture: expected a PNG, JPEG or WebP image, found a GIF image in \"" +
                           output_path("gif-image/image.gif") + "\"; ignored"));
  CHECK_THAT(r.output, !Catch::Contains("\"\""));  // quoted once, not twice
}

TEST_CASE("cli limits: a glTF file whose only node is singular says it draws nothing", "[cli][limits]") {
  std::string buffer;
  rt::test::append<float>(buffer, {-1, -1, 0, 1, -1, 0, 0, 1, 0});
  const rt::Json doc = {{"scenes", {{{"nodes", {0}}}}},
                        {"nodes", {{{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1}}}}},
                        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                        {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}}};
  const std::string model = rt::test::write_gltf("flattened.gltf", buffer, doc);
  const Run r =
      rtcli_bounded("render '" + model + "' -q --width 8 --height 8 -o '" + output_path("flattened.png") + "'");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("warning: the glTF file has no triangles to render: every node of it that "
                                       "carries a mesh has a singular world transform"));
}

TEST_CASE("cli limits: a glTF file with a warning per primitive is validated in linear time", "[cli][limits]") {
  // 50,000 point primitives, a warning each: finding every warning's line:column in the 2 MB
  // text took quadratic time (minutes); only the first of a file's problems are placed now.
  std::string buffer;
  rt::test::append<float>(buffer, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  rt::Json primitives = rt::Json::array();
  for (int i = 0; i < 50000; ++i) primitives.push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 0}});
  const std::string model = rt::test::write_gltf(
      "many-warnings.gltf", buffer,
      {{"scenes", {{{"nodes", {0}}}}},
       {"nodes", {{{"mesh", 0}}}},
       {"meshes", {{{"primitives", primitives}}}},
       {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
       {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}}});
  const Run r = rtcli_bounded("validate --json '" + model + "'");
  CHECK(r.code == 0);  // warnings only
  const rt::Json list = rt::Json::parse(r.output.substr(r.output.find('[')));
  CHECK(list.size() >= 50000);
  size_t placed = 0;
  for (const rt::Json& d : list) placed += d["line"].is_number() ? 1 : 0;
  CHECK(placed == 100);
}
