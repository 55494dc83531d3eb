// Scenes that include other scene files ("include") and place named templates ("templates",
// "template"): what wins where a key is given twice, where an included file's problems are
// reported (its own file:line:column), cycles and repeats refused, templates placed many times
// with their own transforms and materials, sharing their meshes.
#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

#include "io/scene_validator.h"
#include "tests/support/loading.h"

namespace fs = std::filesystem;
using namespace rt;

namespace {

std::string write(const std::string& folder, const std::string& name, const std::string& text) {
  const std::string path = folder + "/" + name;
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << text;
  return path;
}

Diagnostics load_errors(const std::string& path) {
  Diagnostics diags;
  load_scene(path, rt::test::load_options(), diags);
  return diags;
}

const Diagnostic* find_error(const Diagnostics& diags, const std::string& message) {
  for (const Diagnostic& d : diags.all())
    if (d.severity == Severity::kError && d.message.find(message) != std::string::npos) return &d;
  return nullptr;
}

std::string all(const Diagnostics& diags) {
  std::string out;
  for (const Diagnostic& d : diags.all()) out += format_diagnostic(d) + "\n";
  return out;
}

const char* kLibrary = R"({
  // a material library with a template
  "materials": {
    "red": {"kd": [0.8, 0.1, 0.1]},
    "steel": {"kd": 0.2, "ks": 0.8}
  },
  "render": {"width": 64, "height": 48, "seed": 7},
  "lights": [{"type": "point", "position": [0, 5, 5]}],
  "templates": {
    "stool": {"children": [
      {"name": "seat", "shape": "cylinder", "material": "red", "transform": {"translate": [0, 1, 0], "scale": [0.5, 0.5, 0.05], "rotate": [90, 0, 0]}},
      {"name": "leg", "shape": "cylinder", "transform": {"scale": [0.05, 0.05, 1], "rotate": [-90, 0, 0]}},
      {"mesh": {"file": "knot.glb"}, "transform": {"translate": [0, 1.3, 0], "scale": 0.1}}
    ]}
  }
})";

}  // namespace

TEST_CASE("includes: included files' keys first, the including file's win, materials by name, lights add up",
          "[io][include]") {
  const std::string dir = rt::test::fresh_folder("include-merge");
  write(dir, "lib/library.json", kLibrary);
  fs::copy_file(rt::test::source_path("scenes/models/knot.glb"), dir + "/lib/knot.glb",
                fs::copy_options::overwrite_existing);
  const std::string scene = write(dir, "scene.json", R"({
  "include": ["lib/library.json"],
  "render": {"width": 80},
  "camera": {"position": [0, 2, 6], "look_at": [0, 1, 0]},
  "materials": {"red": {"kd": [0.1, 0.7, 0.1]}},
  "lights": [{"type": "point", "position": [3, 5, 0]}],
  "nodes": [
    {"name": "a", "template": "stool", "material": "steel", "transform": {"translate": [-1, 0, 0]}},
    {"name": "b", "template": "stool", "material": "red", "materials": {"steel": "red"}, "transform": {"translate": [1, 0, 0]}},
    {"template": "stool", "material": "steel", "transform": {"translate": [0, 0, -2]}}
  ]
})");
  const LoadedScene loaded = rt::test::load_scene_file(scene);
  CHECK(loaded.settings.width == 80);   // the scene's own
  CHECK(loaded.settings.height == 48);  // the library's, not overridden
  CHECK(loaded.settings.seed == 7);
  CHECK(loaded.graph.lights.size() == 2);
  // "red" is the scene's green everywhere it is used, the library's template too.
  const SceneAssets& assets = *loaded.scene.assets;
  bool green = false, old_red = false;
  for (const Material& m : assets.materials) {
    green = green || m.kd == Vec3(0.1f, 0.7f, 0.1f);
    old_red = old_red || m.kd == Vec3(0.8f, 0.1f, 0.1f);
  }
  CHECK(green);
  CHECK_FALSE(old_red);
  // Three stools: six shapes, three knots; one knot mesh loaded once (instanced, not copied).
  CHECK(loaded.scene.bvh.shapes().size() == 6);
  CHECK(loaded.scene.bvh.instances().size() == 3);
  CHECK(assets.meshes.size() == 1);
  // Names inside a placed template: "<placement>/<name>"; an unnamed placement's stay unnamed.
  std::vector<std::string> names;
  for (const SceneNode& n : loaded.graph.nodes)
    if (!n.name.empty()) names.push_back(n.name);
  CHECK(std::count(names.begin(), names.end(), "a/seat") == 1);
  CHECK(std::count(names.begin(), names.end(), "b/leg") == 1);
  CHECK(std::count(names.begin(), names.end(), "seat") == 0);
  // The legs: steel in "a" (the placement's material), red (swapped from steel) in "b".
  // Every file read is an input (what `watch` watches).
  CHECK(std::count(loaded.inputs.begin(), loaded.inputs.end(), dir + "/lib/library.json") == 1);
  CHECK(loaded.inputs.front() == scene);
}

TEST_CASE("includes: problems in an included file are reported in it, at its line:column", "[io][include][errors]") {
  const std::string dir = rt::test::fresh_folder("include-errors");
  write(dir, "lib/broken.json", "{\n  \"materials\": {\"red\": {\"kd\": [0.8, 0.1, \"x\"]}}\n}\n");
  const std::string scene = write(dir, "scene.json", R"({
  "include": ["lib/broken.json"],
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "nodes": [{"shape": "sphere", "material": "red"}]
})");
  const Diagnostics diags = load_errors(scene);
  INFO(all(diags));
  const Diagnostic* d = find_error(diags, "expected a number >= 0, found the string \"x\"");
  REQUIRE(d);
  CHECK(d->file == dir + "/lib/broken.json");
  CHECK(d->line == 2);
  CHECK(d->column == 42);
  CHECK(d->pointer == "/materials/red/kd/2");
  CHECK(d->excerpt.find("\"x\"") != std::string::npos);
  // validate says the same.
  const Diagnostics v = validate_file(scene, rt::test::load_options());
  CHECK(find_error(v, "found the string \"x\""));
}

TEST_CASE("includes: a missing file, a cycle, a repeat and a non-list are refused at the entry",
          "[io][include][errors]") {
  const std::string dir = rt::test::fresh_folder("include-refused");
  write(dir, "a.json", R"({"include": ["b.json"]})");
  write(dir, "b.json", R"({"include": ["a.json"]})");
  write(dir, "c.json", R"({"materials": {"m": {"kd": 0.5}}})");
  const std::string scene = write(dir, "scene.json", R"({
  "include": ["a.json", "c.json", "c.json", "missing.json", ""],
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "nodes": [{"shape": "sphere", "material": "m"}]
})");
  const Diagnostics diags = load_errors(scene);
  INFO(all(diags));
  const Diagnostic* cycle = find_error(diags, "expected no include cycle, found a.json -> b.json -> a.json");
  REQUIRE(cycle);
  CHECK(cycle->file == dir + "/b.json");
  CHECK(cycle->pointer == "/include/0");
  const Diagnostic* repeat = find_error(diags, "expected each file included once, found \"c.json\" included already");
  REQUIRE(repeat);
  CHECK(repeat->pointer == "/include/2");
  CHECK(repeat->line == 2);
  const Diagnostic* missing = find_error(diags, "expected a readable scene file to include, found \"missing.json\"");
  REQUIRE(missing);
  CHECK(missing->pointer == "/include/3");
  CHECK(find_error(diags, "expected the name of a scene file (.json)"));

  const std::string not_list =
      write(dir, "not-list.json",
            R"({"include": "c.json", "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "nodes": []})");
  CHECK(find_error(load_errors(not_list), "expected an array of scene file names"));
}

TEST_CASE("includes: a camera and nodes may come from any file, but must come from one", "[io][include]") {
  const std::string dir = rt::test::fresh_folder("include-required");
  write(
      dir, "view.json",
      R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "lights": [{"type": "point", "position": [0, 3, 3]}]})");
  write(dir, "things.json", R"({"materials": {"m": {"kd": 0.5}}, "nodes": [{"shape": "sphere", "material": "m"}]})");
  const LoadedScene ok =
      rt::test::load_scene_file(write(dir, "scene.json", R"({"include": ["view.json", "things.json"]})"));
  CHECK(ok.scene.bvh.shapes().size() == 1);
  const Diagnostics none = load_errors(write(dir, "bare.json", R"({"include": ["things.json"]})"));
  INFO(all(none));
  const Diagnostic* d = find_error(none, "missing required key \"camera\"");
  REQUIRE(d);
  CHECK(d->file == dir + "/bare.json");
  CHECK(none.error_count() == 1);  // the schema does not say it again
}

TEST_CASE("templates: unknown names, cycles, shapes left without a material and deep nesting are refused",
          "[io][template][errors]") {
  const std::string dir = rt::test::fresh_folder("template-errors");
  const std::string base = R"("camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "materials": {"m": {"kd": 0.5}},
  "lights": [{"type": "point", "position": [0, 3, 3]}],)";
  const Diagnostics unknown = load_errors(write(dir, "unknown.json", "{" + base + R"(
  "templates": {"ball": {"shape": "sphere", "material": "m"}},
  "nodes": [{"template": "bal"}]})"));
  INFO(all(unknown));
  CHECK(find_error(unknown, "found the undefined name \"bal\" (did you mean \"ball\"?)"));

  const Diagnostics cycle = load_errors(write(dir, "cycle.json", "{" + base + R"(
  "templates": {"a": {"children": [{"template": "b"}]}, "b": {"children": [{"template": "a"}]}},
  "nodes": [{"template": "a"}]})"));
  INFO(all(cycle));
  CHECK(find_error(cycle, "expected templates that do not place themselves, found the cycle \"a\" -> \"b\" -> \"a\""));

  const Diagnostics bare = load_errors(write(dir, "bare.json", "{" + base + R"(
  "templates": {"ball": {"shape": "sphere"}},
  "nodes": [{"template": "ball"}, {"template": "ball", "material": "m"}]})"));
  INFO(all(bare));
  const Diagnostic* d = find_error(bare, "expected a material for every shape of template \"ball\"");
  REQUIRE(d);
  CHECK(d->pointer == "/nodes/0/template");
  CHECK(bare.error_count() == 1);  // the second placement gives one

  const Diagnostics both = load_errors(write(dir, "both.json", "{" + base + R"(
  "templates": {"ball": {"shape": "sphere", "material": "m"}},
  "nodes": [{"template": "ball", "shape": "cube", "material": "m"}]})"));
  INFO(all(both));
  CHECK(find_error(both, "expected either \"template\" or \"shape\" on one node"));

  // A chain of templates, each placing the next twice: refused by the nesting limit before it
  // grows (2^200 nodes otherwise).
  std::string chain = R"("templates": {"t0": {"shape": "sphere", "material": "m"})";
  for (int i = 1; i <= 200; ++i)
    chain += ", \"t" + std::to_string(i) + "\": {\"children\": [{\"template\": \"t" + std::to_string(i - 1) +
             "\"}, {\"template\": \"t" + std::to_string(i - 1) + "\"}]}";
  chain += "}";
  const Diagnostics deep =
      load_errors(write(dir, "deep.json", "{" + base + chain + R"(, "nodes": [{"template": "t200"}]})"));
  CHECK(deep.has_errors());
  const std::string wide = R"("templates": {"t0": {"shape": "sphere", "material": "m"})";
  std::string fan = wide;
  for (int i = 1; i <= 40; ++i) {
    fan += ", \"t" + std::to_string(i) + "\": {\"children\": [";
    for (int k = 0; k < 8; ++k)
      fan += std::string(k ? ", " : "") + "{\"template\": \"t" + std::to_string(i - 1) + "\"}";
    fan += "]}";
  }
  fan += "}";
  const Diagnostics many =
      load_errors(write(dir, "many.json", "{" + base + fan + R"(, "nodes": [{"template": "t40"}]})"));
  INFO(all(many));
  CHECK(find_error(many, "nodes in a scene, found more once templates are placed"));
}
