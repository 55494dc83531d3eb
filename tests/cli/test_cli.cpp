// The rtcli binary as a user runs it: exit codes, messages, files written and files left alone.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>

#include <catch2/catch.hpp>

#include "io/image/image_header.h"
#include "io/json/document.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;
using rt::test::output_path;
using rt::test::read_file;
using rt::test::rtcli;
using rt::test::Run;
using rt::test::source_path;
using rt::test::write_file;

namespace {

std::string small(const std::string& extra = "") { return "--width 40 --height 24 " + extra; }

}  // namespace

TEST_CASE("cli: --version, --help, render --help", "[cli]") {
  Run r = rtcli("--version");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::StartsWith("rtcli 0."));
  r = rtcli("--help");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("render") && Catch::Contains("bench"));
  r = rtcli("render --help");
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("--threads") && Catch::Contains("--seed") && Catch::Contains("--quiet"));
}

TEST_CASE("cli: bad usage exits 2 with a message", "[cli]") {
  for (const char* args :
       {"", "render", "frobnicate", "render scenes/default.json --bogus", "render scenes/default.json --threads 0",
        "render scenes/default.json --width -5", "render scenes/default.json --seed banana",
        "render scenes/default.json --glossy-samples 0", "render scenes/default.json --glossy-samples 257"}) {
    INFO(args);
    const Run r = rtcli(args);
    CHECK(r.code == 2);
    CHECK_FALSE(r.output.empty());
  }
}

TEST_CASE("cli: a misspelt command, option or option value gets the nearest real one", "[cli]") {
  const std::pair<const char*, const char*> cases[] = {
      {"rendr scenes/default.json", "unknown command \"rendr\" (did you mean \"render\"?)"},
      {"render scenes/default.json --widht 5", "render: unknown option \"--widht\" (did you mean \"--width\"?)"},
      {"validate --jsn scenes/default.json", "validate: unknown option \"--jsn\" (did you mean \"--json\"?)"},
      {"render scenes/default.json --aa adaptve",
       "unknown anti-aliasing mode \"adaptve\" (did you mean \"adaptive\"?)"},
      {"render scenes/default.json --integrator normal", "(did you mean \"normals\"?)"},
  };
  for (const auto& [args, expected] : cases) {
    INFO(args);
    const Run r = rtcli(args);
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains(expected));
  }
  // Nothing near: no guess, and the list of what there is.
  const Run far = rtcli("frobnicate");
  CHECK(far.code == 2);
  CHECK_THAT(far.output,
             Catch::Contains("unknown command \"frobnicate\"; expected one of: render, watch, validate, bench"));
}

TEST_CASE("cli: render writes the PNG, prints a summary and where it wrote", "[cli]") {
  const std::string out = output_path("cli-default.png");
  fs::remove(out);
  const Run r = rtcli("render scenes/default.json -o '" + out + "' " + small("--threads 2"));
  REQUIRE(r.code == 0);
  CHECK(fs::file_size(out) > 100);
  CHECK_THAT(r.output, Catch::Contains("40x24") && Catch::Contains("Mrays/s") && Catch::Contains("2 threads") &&
                           Catch::Contains("wrote " + out));
  CHECK(read_file(out).substr(1, 3) == "PNG");
}

TEST_CASE("cli: the summary counts rays by kind, --glossy-samples and --no-glossy change them", "[cli][glossy]") {
  const std::string out = output_path("cli-glossy.png");
  Run r = rtcli("render scenes/glossy.json -q -o '" + out + "' " + small());
  CHECK(r.code == 0);
  CHECK(r.output.empty());
  const auto glossy_rays = [](const std::string& args) {
    const Run run = rtcli("render scenes/glossy.json -o '" + output_path("cli-glossy.png") + "' " + args);
    REQUIRE(run.code == 0);
    CHECK_THAT(run.output, Catch::Contains(" camera, ") && Catch::Contains(" shadow, ") &&
                               Catch::Contains(" reflection, ") && Catch::Contains(" refraction, ") &&
                               Catch::Contains(" bounce)"));
    const size_t end = run.output.find(" glossy, ");
    REQUIRE(end != std::string::npos);
    const size_t start = run.output.rfind(", ", end) + 2;
    return run.output.substr(start, end - start);
  };
  CHECK(glossy_rays(small("--no-glossy")) == "0");
  CHECK(glossy_rays(small("--glossy-samples 1")) != "0");
  CHECK(glossy_rays(small("--glossy-samples 1")) != glossy_rays(small("--glossy-samples 64")));
}

TEST_CASE("cli: --integrator picks a debug view, an unknown name lists the valid ones", "[cli]") {
  for (const char* name : {"normals", "uv", "depth", "albedo", "whitted", "path"}) {
    const std::string out = output_path(std::string("cli-") + name + ".png");
    fs::remove(out);
    INFO(name);
    CHECK(rtcli("render scenes/primitives.json -q --integrator " + std::string(name) + " -o '" + out + "' " + small())
              .code == 0);
    CHECK(fs::exists(out));
  }
  const Run r = rtcli("render scenes/primitives.json --integrator normal -o '" + output_path("cli-x.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("unknown integrator \"normal\" (did you mean \"normals\"?)") &&
                           Catch::Contains("expected one of: whitted, path, normals, uv, depth, albedo"));
  CHECK_FALSE(fs::exists(output_path("cli-x.png")));
}

TEST_CASE("cli: without -o the image is named after the scene, in the current folder", "[cli]") {
  const std::string folder = output_path("cwd-test");
  fs::create_directories(folder);
  fs::remove(folder + "/primitives.png");
  const Run r = rtcli("render '" + source_path("scenes/primitives.json") + "' " + small("--quiet"), folder);
  REQUIRE(r.code == 0);
  CHECK(r.output.empty());  // --quiet
  CHECK(fs::exists(folder + "/primitives.png"));
}

TEST_CASE("cli: a glTF model renders directly", "[cli]") {
  const Run r = rtcli("render scenes/models/knot.glb -o '" + output_path("knot.png") + "' " + small());
  CHECK(r.code == 0);
}

TEST_CASE("cli: 1 thread and 2 threads give byte-identical PNG files", "[cli][determinism]") {
  for (const char* scene : {"scenes/primitives.json", "scenes/csg.json"}) {
    INFO(scene);
    const std::string a = output_path("threads1.png"), b = output_path("threads2.png");
    REQUIRE(rtcli(std::string("render ") + scene + " -q --width 120 --height 70 --threads 1 -o '" + a + "'").code == 0);
    REQUIRE(rtcli(std::string("render ") + scene + " -q --width 120 --height 70 --threads 2 -o '" + b + "'").code == 0);
    CHECK(read_file(a) == read_file(b));
  }
}

TEST_CASE("cli: bad scenes exit 2 and leave an existing output untouched", "[cli][errors]") {
  // A folder of its own: other tests may be writing temporary files next to theirs meanwhile.
  fs::create_directories(output_path("untouched"));
  const std::string out = output_path("untouched/precious.png");
  write_file("untouched/precious.png", "the good image from yesterday");
  const std::string bad = write_file("bad-material.json", R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "materials": {"red": {"kd": [1, 0, 0]}},
  "nodes": [{"shape": "sphere", "material": "blue"}]
})");
  const Run r = rtcli("render '" + bad + "' -o '" + out + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output,
             Catch::Contains("bad-material.json:4:45: error: /nodes/0/material: expected the name of a material"));
  CHECK(read_file(out) == "the good image from yesterday");
  for (const auto& entry : fs::directory_iterator(output_path("untouched")))
    CHECK(entry.path().filename().string().find(".rtcli-") == std::string::npos);  // no temporary left behind

  const Run missing = rtcli("render no-such-scene.json -o '" + out + "'");
  CHECK(missing.code == 2);
  CHECK_THAT(missing.output, Catch::Contains("no-such-scene.json: error: file not found"));
  CHECK(read_file(out) == "the good image from yesterday");
}

TEST_CASE("cli: an output that cannot be written is refused before rendering", "[cli][errors]") {
  Run r = rtcli("render scenes/default.json -o /no/such/folder/x.png");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("does not exist"));
  r = rtcli("render scenes/default.json -o '" + output_path("image.bmp") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains(".png, .exr or .jpg"));
}

TEST_CASE("cli: bench runs on a small model, and replays the rays it saved", "[cli][bench]") {
  const std::string rays = output_path("gem.rays");
  fs::remove(rays);
  Run r = rtcli(
      "bench scenes/models/gem.gltf --scene scenes/default.json --path-scene scenes/default.json --repeats 1 "
      "--save-rays '" +
      rays + "'");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("BVH build, cold") && Catch::Contains("BVH build, warm") &&
                           Catch::Contains("incoherent (Mray/s)") && Catch::Contains("occlusion (Mray/s)") &&
                           Catch::Contains("the median of 1 runs") && Catch::Contains("render default.json"));
  CHECK_THAT(r.output, Catch::Contains("path trace default.json (160x100, 16 spp)") && Catch::Contains("Msamples/s") &&
                           Catch::Contains(" bounce"));
  CHECK_THAT(r.output, Catch::Contains("rays: generated: primary 2073600 incoherent 2000000 occlusion "));
  REQUIRE(fs::exists(rays));
  r = rtcli("bench scenes/models/gem.gltf --scene '' --path-scene '' --repeats 1 --rays '" + rays + "'");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("gem.rays: primary 2073600 incoherent 2000000 occlusion "));
  // A ray file cut short is refused before anything is built, and named.
  fs::resize_file(rays, 1000);
  r = rtcli("bench --path-scene '' --rays '" + rays + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("gem.rays: ray set 1 of 3 is cut short or malformed"));
  fs::remove(rays);
}

TEST_CASE("cli: --aa picks the anti-aliasing mode, --aa-debug writes and names the refinement images",
          "[cli][antialias]") {
  Run r = rtcli("render scenes/default.json -o '" + output_path("cli-aa-bad.png") + "' --aa superb");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--aa: unknown anti-aliasing mode \"superb\"; expected one of: none, "
                                       "uniform, adaptive"));
  for (const char* args : {"--aa-depth 5", "--aa-threshold 1.5", "--aa-samples 0", "--aa-samples 17"}) {
    INFO(args);
    CHECK(rtcli("render scenes/default.json " + std::string(args)).code == 2);
  }

  const std::string out = output_path("cli-aa.png");
  const std::string refined = output_path("cli-aa.aa-refined.png"), depth = output_path("cli-aa.aa-depth.png");
  for (const std::string& f : {out, refined, depth}) fs::remove(f);
  r = rtcli("render scenes/antialias.json -o '" + out + "' " + small("--aa adaptive --aa-depth 3 --aa-debug"));
  REQUIRE(r.code == 0);
  for (const std::string& f : {out, refined, depth}) {
    INFO(f);
    CHECK(read_file(f).substr(1, 3) == "PNG");
    CHECK_THAT(r.output, Catch::Contains("wrote " + f));
  }
  CHECK_THAT(r.output,
             Catch::Contains("camera rays)") && Catch::Contains("% of pixels refined (anti-aliasing adaptive)"));
  CHECK(read_file(refined) != read_file(out));  // some pixels are red

  // --aa none on the same scene: one camera ray a pixel, nothing refined.
  r = rtcli("render scenes/antialias.json -o '" + out + "' " + small("--aa none"));
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("(1.00 camera rays), 0.0% of pixels refined (anti-aliasing none)"));
}

TEST_CASE("cli: --stats writes the render's figures as JSON", "[cli][stats]") {
  const std::string png = output_path("stats.png"), stats = output_path("stats.json");
  fs::remove(stats);
  const Run r = rtcli("render scenes/soft_shadows.json --width 40 --height 24 --shadow-samples 4 -o '" + png +
                      "' --stats '" + stats + "'");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("wrote " + stats));
  const rt::Json j = rt::Json::parse(read_file(stats));
  CHECK(j["width"] == 40);
  CHECK(j["height"] == 24);
  CHECK(j["shadow_samples"] == 4);
  CHECK(j["outputs"][0] == png);
  CHECK(j["stereo"] == "none");
  uint64_t sum = 0;
  for (const char* kind : {"camera", "shadow", "reflection", "refraction", "glossy"})
    sum += j["rays"][kind].get<uint64_t>();
  CHECK(j["rays"]["total"].get<uint64_t>() == sum);
  CHECK(j["rays"]["shadow"].get<uint64_t>() > 0);
  CHECK(j["rays_per_pixel"].get<double>() == Approx(static_cast<double>(sum) / (40.0 * 24.0)));
  CHECK(j["seconds"]["render"].get<double>() > 0.0);
  // A stats file that cannot be written is refused before rendering.
  const Run bad = rtcli("render scenes/soft_shadows.json --width 40 --height 24 -o '" + png +
                        "' --stats /nonexistent-folder/stats.json");
  CHECK(bad.code == 2);
}

TEST_CASE("cli: -o NAME.jpg writes a JPEG of the image's size, frames need a GIF or numbered PNGs", "[cli][jpeg]") {
  const std::string jpg = output_path("render.jpg");
  fs::remove(jpg);
  REQUIRE(rtcli("render scenes/primitives.json -q --width 64 --height 36 -o '" + jpg + "'").code == 0);
  const std::string bytes = read_file(jpg);
  REQUIRE(bytes.size() > 100);
  std::string error;
  const auto header = rt::read_image_header(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), error);
  REQUIRE(header);
  CHECK(std::string(rt::image_format_name(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size())) ==
        "JPEG");
  CHECK(header->width == 64u);
  CHECK(header->height == 36u);
  const Run r = rtcli("render scenes/turntable.json --frames 0-2 -o '" + output_path("frames.jpg") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("need an animated GIF"));
}

TEST_CASE("cli: --secondary-shadows takes scaled or full, and the stats say which", "[cli][lights]") {
  Run r = rtcli("render scenes/default.json --secondary-shadows half");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--secondary-shadows: unknown secondary shadow rule \"half\"; expected one of: "
                                       "full, scaled"));
  const std::string stats = output_path("secondary.json");
  r = rtcli("render scenes/soft_shadows.json --width 32 --height 18 --secondary-shadows full -o '" +
            output_path("secondary.png") + "' --stats '" + stats + "'");
  REQUIRE(r.code == 0);
  CHECK_THAT(read_file(stats), Catch::Contains("\"secondary_shadows\": \"full\""));
}

TEST_CASE("cli: --preview renders a draft: one ray a pixel, a quarter of the shadow and glossy samples", "[cli]") {
  const std::string stats = output_path("preview.json"), image = output_path("preview.png");
  Run r = rtcli("render scenes/csg.json --width 64 --height 36 --preview -o '" + image + "' --stats '" + stats + "'");
  REQUIRE(r.code == 0);
  std::string s = read_file(stats);
  CHECK_THAT(s, Catch::Contains("\"antialias\": \"none\"") && Catch::Contains("\"shadow_samples\": 4") &&
                    Catch::Contains("\"camera_rays_per_pixel\": 1.0"));
  // An option beside it still wins.
  r = rtcli("render scenes/csg.json --width 64 --height 36 --preview --shadow-samples 9 -o '" + image + "' --stats '" +
            stats + "'");
  REQUIRE(r.code == 0);
  s = read_file(stats);
  CHECK_THAT(s, Catch::Contains("\"shadow_samples\": 9") && Catch::Contains("\"antialias\": \"none\""));
}

TEST_CASE("cli: --exposure and --tone-map, and render.exposure and render.tone_map in a scene", "[cli][tonemap]") {
  Run r = rtcli("render scenes/default.json --tone-map film");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--tone-map: unknown tone curve \"film\"") &&
                           Catch::Contains("expected one of: clamp, filmic"));
  r = rtcli("render scenes/default.json --exposure 21");
  CHECK(r.code == 2);
  // The clamp rule with exposure 0 is the default: the same bytes as without the options.
  const std::string plain = output_path("tone_plain.png"), clamp = output_path("tone_clamp.png");
  const std::string filmic = output_path("tone_filmic.png"), stats = output_path("tone.json");
  REQUIRE(rtcli("render scenes/soft_shadows.json " + small("-o '" + plain + "'")).code == 0);
  REQUIRE(rtcli("render scenes/soft_shadows.json " + small("--tone-map clamp --exposure 0 -o '" + clamp + "'")).code ==
          0);
  CHECK(read_file(plain) == read_file(clamp));
  r = rtcli("render scenes/soft_shadows.json " +
            small("--tone-map filmic --exposure 1.5 -o '" + filmic + "' --stats '" + stats + "'"));
  REQUIRE(r.code == 0);
  CHECK(read_file(filmic) != read_file(plain));
  const std::string s = read_file(stats);
  CHECK_THAT(s, Catch::Contains("\"tone_map\": \"filmic\"") && Catch::Contains("\"exposure\": 1.5"));
  // A debug view is data, never tone mapped.
  const std::string normals_plain = output_path("tone_normals_plain.png"), normals = output_path("tone_normals.png");
  REQUIRE(rtcli("render scenes/soft_shadows.json " + small("--integrator normals -o '" + normals_plain + "'")).code ==
          0);
  REQUIRE(rtcli("render scenes/soft_shadows.json " + small("--integrator normals --tone-map filmic --exposure 2 -o '" +
                                                           normals + "' --stats '" + stats + "'"))
              .code == 0);
  CHECK(read_file(normals) == read_file(normals_plain));
  CHECK_THAT(read_file(stats), Catch::Contains("\"tone_map\": \"clamp\"") && Catch::Contains("\"exposure\": 0.0"));
  // The scene keys, and a bad one reported with its place.
  std::string scene =
      write_file("tone_scene.json", R"({"render": {"width": 16, "height": 9, "tone_map": "filmic", "exposure": -1},
    "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0]},
    "lights": [{"type": "point", "position": [1, 2, 3]}],
    "materials": {"m": {"kd": 0.8}}, "nodes": [{"shape": "sphere", "material": "m"}]})");
  r = rtcli("render '" + scene + "' -q -o '" + output_path("tone_scene.png") + "' --stats '" + stats + "'");
  REQUIRE(r.code == 0);
  CHECK_THAT(read_file(stats), Catch::Contains("\"tone_map\": \"filmic\"") && Catch::Contains("\"exposure\": -1.0"));
  scene = write_file("tone_bad.json",
                     R"({"render": {"tone_map": "aces"}, "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0]},
    "nodes": []})");
  r = rtcli("validate '" + scene + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("/render/tone_map") && Catch::Contains("aces"));
}

TEST_CASE("cli: a looping GIF whose last frame shows the first again ends one frame before it", "[cli][animation]") {
  const std::string out = rt::test::fresh_folder("gif-loop");
  const auto scene = [&](int degrees) {
    return rt::test::write_file("gif-loop/turn" + std::to_string(degrees) + ".json",
                                R"({"render": {"width": 16, "height": 12},
 "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0]},
 "materials": {"m": {"kd": [0.8, 0.2, 0.2]}},
 "lights": [{"type": "point", "position": [2, 4, 3]}],
 "nodes": [{"name": "box", "shape": "cube", "material": "m"}],
 "animation": {"fps": 12, "tracks": [{"node": "box", "property": "rotate",
   "keys": [{"frame": 0, "value": {"axis": [0, 1, 0], "degrees": 0}},
            {"frame": 12, "value": {"axis": [0, 1, 0], "degrees": )" +
                                    std::to_string(degrees) + "}}]}]}}");
  };
  const auto frames = [&](const std::string& path, const std::string& output) {
    const std::string stats = out + "/stats.json";
    REQUIRE(rt::test::rtcli("render '" + path + "' -q -o '" + out + "/" + output + "' --stats '" + stats + "'").code ==
            0);
    return rt::Json::parse(rt::test::read_file(stats))["frame_list"].get<std::string>();
  };
  CHECK(frames(scene(360), "loop.gif") == "0-11");       // frame 12 is frame 0 again: 12 frames
  CHECK(frames(scene(360), "loop_####.png") == "0-12");  // numbered frames: every one
  CHECK(frames(scene(270), "quarter.gif") == "0-12");    // not a loop: every frame
}
