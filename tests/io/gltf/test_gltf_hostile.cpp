// glTF files written to hurt: offsets that wrap 64-bit arithmetic, counts that would allocate
// gigabytes, node graphs that grow exponentially, special files as buffers, required extensions,
// absurd nesting. Each is refused with a sentence, quickly and before any large allocation.
#include <sys/stat.h>

#include <cctype>
#include <chrono>
#include <cstring>
#include <filesystem>

#include <catch2/catch.hpp>

#include "io/gltf/loader.h"
#include "io/scene_loader.h"
#include "tests/support/gltf_files.h"
#include "tests/support/gltf_import.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;
using rt::test::square_positions;
using rt::test::write_gltf;

namespace {

// One triangle over the square's first three vertices; each case breaks one thing in it.
Json triangle() {
  return {{"scenes", {{{"nodes", {0}}}}},
          {"nodes", {{{"mesh", 0}}}},
          {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
          {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
          {"bufferViews", {{{"buffer", 0}, {"byteLength", 48}}}}};
}

struct Outcome {
  bool loaded = false;
  std::string error;
  double seconds = 0.0;
  std::string pointer;  // the first error's, inside the glTF file
  size_t line = 0, column = 0;
};

Outcome import_file(const std::string& path, const LoadLimits& limits = {}) {
  const auto start = std::chrono::steady_clock::now();
  rt::test::ImportProblems error;
  Outcome o;
  o.loaded = import_gltf(path, std::nullopt, limits, error).has_value();
  o.error = error.message;
  if (const Diagnostic* d = error.first_error()) {
    o.pointer = d->pointer;
    o.line = d->line;
    o.column = d->column;
  }
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return o;
}

Outcome import_json(const std::string& name, const Json& doc) {
  return import_file(write_gltf(name, square_positions(), doc));
}

}  // namespace

TEST_CASE("glTF hostile: offsets near 2^64 cannot wrap the bounds checks", "[io][gltf][hostile]") {
  Json doc = triangle();
  doc["bufferViews"][0]["byteOffset"] = 18446744073709551600ull;  // + byteLength wraps to 32
  Outcome o = import_json("wrap-view.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("bufferView 0 (bytes 18446744073709551600 + 48) does not lie inside buffer 0"));
  doc = triangle();
  doc["accessors"][0]["byteOffset"] = 18446744073709551604ull;  // + 36 wraps to 24
  o = import_json("wrap-accessor.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("do not fit in bufferView 0"));
  doc = triangle();
  doc["bufferViews"][0]["byteStride"] = 12;
  doc["accessors"][0]["count"] = 1537228672809129302ull;  // stride * (count - 1) wraps
  o = import_json("wrap-stride.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK(o.seconds < 1.0);
}

TEST_CASE("glTF hostile: counts are checked against the data and the limits before allocating", "[io][gltf][hostile]") {
  Json doc = triangle();
  doc["accessors"][0]["count"] = 268435456;  // 2^28 elements in a 48-byte view
  Outcome o = import_json("huge-count.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("expected at most 33554432 vertices in a scene's meshes, found 268435456"));
  CHECK(o.seconds < 1.0);
  doc["accessors"][0].erase("bufferView");  // valid glTF: all zeros; still over the limit
  o = import_json("huge-zeros.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK(o.seconds < 1.0);
  doc = triangle();
  doc["accessors"][0]["sparse"] = {{"count", 2147483647},
                                   {"indices", {{"bufferView", 0}, {"componentType", 5125}}},
                                   {"values", {{"bufferView", 0}}}};
  o = import_json("huge-sparse.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("substitutes 2147483647 elements; glTF requires 1 to count (3)"));
  doc["accessors"][0]["count"] = 3;
  doc["accessors"][0]["sparse"]["count"] = 2;  // indices 0x0, 0x3f800000 (the floats 0 and 1): out of range
  o = import_json("sparse-past-end.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("sparse accessor 0 substitutes element"));
  // The limit is the caller's: a small one refuses what the default accepts.
  LoadLimits small;
  small.vertices = 2;
  CHECK_FALSE(import_file(write_gltf("three.gltf", square_positions(), triangle()), small).loaded);
}

TEST_CASE("glTF hostile: what the specification forbids is refused", "[io][gltf][hostile]") {
  std::string buffer = square_positions();
  rt::test::append<float>(buffer, {0, 1, 2});
  Json doc = triangle();
  doc["meshes"][0]["primitives"][0]["indices"] = 1;
  doc["accessors"].push_back({{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "SCALAR"}});
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}});
  Outcome o = import_file(write_gltf("float-indices.gltf", buffer, doc));
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("index accessor 1 has component type FLOAT; glTF allows only UNSIGNED_BYTE"));

  doc = triangle();
  doc["extensionsUsed"] = doc["extensionsRequired"] = {"KHR_materials_diffuse_transmission"};
  o = import_json("required.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error,
             Catch::Contains("requires the extension \"KHR_materials_diffuse_transmission\", which rtcli does not"));
  doc["extensionsUsed"] = doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  CHECK(import_json("quantization.gltf", doc).loaded);  // implemented: any component type is read
  // An accessor without a bufferView (as an unsupported compression writes them) is refused by
  // tinygltf first: the reason named is still the extension, at its place in the file.
  doc = triangle();
  doc["accessors"][0].erase("bufferView");
  doc["extensionsUsed"] = doc["extensionsRequired"] = {"KHR_mesh_quantization", "KHR_materials_diffuse_transmission"};
  rt::test::ImportProblems draco;
  CHECK_FALSE(import_gltf(write_gltf("draco.gltf", square_positions(), doc), std::nullopt, {}, draco));
  REQUIRE(draco.found.error_count() == 1);
  const Diagnostic& named = draco.found.all().front();
  CHECK(named.pointer == "/extensionsRequired/1");
  CHECK(named.line > 0);
  CHECK_THAT(named.message, Catch::Contains("requires the extension \"KHR_materials_diffuse_transmission\""));
  doc = triangle();
  doc["extensionsUsed"] = {"EXT_fancy_sparkles"};  // optional and unknown: a warning, and it renders
  rt::test::ImportProblems optional_error;
  const auto optional =
      import_gltf(write_gltf("optional.gltf", square_positions(), doc), std::nullopt, {}, optional_error);
  REQUIRE(optional);
  REQUIRE(optional_error.warnings.size() == 1);
  CHECK_THAT(optional_error.warnings[0], Catch::Contains("\"EXT_fancy_sparkles\", which rtcli ignores"));
  // Reported where the file says it, with the line and column of its text.
  const Diagnostic& used = optional_error.found.all().front();
  CHECK(used.pointer == "/extensionsUsed/0");
  CHECK(used.line == 1);
  CHECK(used.column > 1);

  doc = triangle();
  doc["bufferViews"][0]["byteStride"] = 13;
  o = import_json("stride-13.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("byteStride") && Catch::Contains("13"));
}

TEST_CASE("glTF hostile: node graphs are trees, walked once", "[io][gltf][hostile]") {
  // Each node lists the next twice: 2^24 paths to the last one if walked naively.
  Json doc = triangle();
  doc["nodes"] = Json::array();
  for (int i = 0; i < 24; ++i) doc["nodes"].push_back({{"children", {i + 1, i + 1}}});
  doc["nodes"].push_back({{"mesh", 0}});
  Outcome o = import_json("doubling.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error,
             Catch::Contains(
                 "node 1 is a child of node 0 and of node 0; glTF requires every node to have at most one parent"));
  CHECK(o.seconds < 1.0);

  doc["nodes"] = {{{"children", {1}}}, {{"children", {0}}, {"mesh", 0}}};  // a cycle
  o = import_json("cycle.gltf", doc);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("the scene lists node 0, which is a child of node 1"));

  doc["nodes"] = {{{"mesh", 0}}};
  doc["scenes"][0]["nodes"] = {0, 0};
  CHECK_THAT(import_json("root-twice.gltf", doc).error, Catch::Contains("lists node 0 twice"));

  // A long chain is fine, and walked without recursion.
  doc["nodes"] = Json::array();
  for (int i = 0; i < 20000; ++i) doc["nodes"].push_back({{"children", {i + 1}}});
  doc["nodes"].push_back({{"mesh", 0}});
  doc["scenes"][0]["nodes"] = {0};
  o = import_json("chain.gltf", doc);
  CHECK(o.loaded);
}

TEST_CASE("glTF hostile: buffers must be regular files, and the JSON sane", "[io][gltf][hostile]") {
  Json doc = triangle();
  doc["asset"] = {{"version", "2.0"}};
  // A link to /dev/zero beside the model (tinygltf resolves URIs against the model's folder):
  // it leaves the folder, and where that is allowed, it is no regular file.
  const std::string zero = rt::test::output_path("zero-link.bin");
  std::filesystem::remove(zero);
  std::filesystem::create_symlink("/dev/zero", zero);
  doc["buffers"] = {{{"byteLength", 48}, {"uri", "zero-link.bin"}}};
  std::string path = rt::test::write_file("dev-zero-buffer.gltf", doc.dump());
  Outcome o = import_file(path);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("\"zero-link.bin\" is outside the model's folder"));
  LoadLimits anywhere;
  anywhere.outside_files = true;
  o = import_file(path, anywhere);
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("is a character device, not a regular file"));

  const std::string fifo = rt::test::output_path("buffer.fifo");
  std::filesystem::remove(fifo);
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  doc["buffers"][0]["uri"] = "buffer.fifo";
  o = import_file(rt::test::write_file("fifo-buffer.gltf", doc.dump()));
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("is a named pipe (FIFO)"));

  // Nesting that tinygltf would walk recursively.
  doc = triangle();
  doc["asset"] = {{"version", "2.0"}};
  std::string text = doc.dump();
  text.insert(text.size() - 1, ", \"extras\": " + std::string(100000, '[') + std::string(100000, ']'));
  o = import_file(rt::test::write_file("deep-extras.gltf", text));
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("nested at most 512 levels"));

  // A .glb whose header announces more JSON than the file holds, and one too short for a header.
  // magic, version 2, total length 64, JSON chunk length 65535, chunk type, then 2 bytes of JSON.
  const char header[] = "glTF\x02\0\0\0\x40\0\0\0\xff\xff\0\0JSON{}";
  const std::string glb(header, sizeof header - 1);
  o = import_file(rt::test::write_file("short-json.glb", glb));
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("the file is truncated"));
  o = import_file(rt::test::write_file("tiny.glb", std::string("glTF\x02\0\0\0", 8)));
  CHECK_FALSE(o.loaded);
  CHECK_THAT(o.error, Catch::Contains("shorter than its 20-byte header"));
}

TEST_CASE("glTF hostile: instancing shares a mesh, the instance limit counts placements", "[io][gltf][hostile]") {
  Json doc = triangle();
  doc["nodes"] = {{{"children", Json::array()}}};
  for (int i = 1; i <= 100; ++i) {
    doc["nodes"][0]["children"].push_back(i);
    doc["nodes"].push_back({{"mesh", 0}, {"translation", {i, 0, 0}}});
  }
  const std::string model = write_gltf("hundred.gltf", square_positions(), doc);
  LoadOptions options = rt::test::load_options();
  options.limits.triangles = 1;  // the one triangle, stored once for its 100 placements
  options.limits.instances = 50;
  Diagnostics diags;
  CHECK_FALSE(load_scene(model, options, diags));
  REQUIRE(diags.has_errors());
  CHECK_THAT(diags.all().front().message, Catch::Contains("at most 50 shapes and placed mesh primitives"));
  options.limits.instances = 100;
  Diagnostics ok;
  const auto loaded = load_scene(model, options, ok);
  REQUIRE(loaded);
  CHECK(loaded->scene.assets->meshes.size() == 1);
  CHECK(loaded->scene.bvh.instances().size() == 100);
  options.limits.triangles = 0;
  Diagnostics few;
  CHECK_FALSE(load_scene(model, options, few));
  REQUIRE(few.has_errors());
  CHECK_THAT(few.all().front().message, Catch::Contains("at most 0 triangles in a scene's meshes"));
}

TEST_CASE("glTF hostile: each refusal names its JSON pointer in the file, and a .gltf's line:column",
          "[io][gltf][hostile][errors]") {
  const auto check = [](const char* name, const Json& doc, const std::string& pointer) {
    // Written over several lines, so that the line is not always 1.
    const std::string text = [&] {
      Json full = doc;
      full["asset"] = {{"version", "2.0"}};
      full["buffers"] = {{{"byteLength", 48},
                          {"uri", "data:application/octet-stream;base64," + rt::test::base64(square_positions())}}};
      return full.dump(2);
    }();
    const std::string path = rt::test::write_file(name, text);
    const Outcome o = import_file(path);
    INFO(name << ": " << o.error);
    CHECK_FALSE(o.loaded);
    CHECK(o.pointer == pointer);
    // The line:column is where the pointer's value starts in the text.
    REQUIRE(o.line > 1);
    size_t offset = 0;
    for (size_t line = 1; line < o.line; ++line) offset = text.find('\n', offset) + 1;
    const std::string key = pointer.substr(pointer.rfind('/') + 1);
    const std::string before = text.substr(offset, o.column - 1);
    const bool in_array = std::isdigit(static_cast<unsigned char>(key[0]));
    if (!in_array) CHECK(before.find("\"" + key + "\"") != std::string::npos);
  };
  Json doc = triangle();
  doc["bufferViews"][0]["byteOffset"] = 18446744073709551600ull;
  check("pointer-wrap.gltf", doc, "/bufferViews/0/byteLength");
  doc = triangle();
  doc["bufferViews"][0]["byteStride"] = 8;  // smaller than a VEC3 of floats (tinygltf refuses 13 itself)
  check("pointer-stride.gltf", doc, "/bufferViews/0/byteStride");
  doc = triangle();
  doc["accessors"][0]["count"] = 400;
  check("pointer-count.gltf", doc, "/accessors/0/count");
  doc = triangle();
  doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7;
  check("pointer-no-accessor.gltf", doc, "/meshes/0/primitives/0/attributes/POSITION");
  doc = triangle();
  doc["nodes"][0]["children"] = {5};
  check("pointer-child.gltf", doc, "/nodes/0/children/0");
  doc = triangle();
  doc["extensionsUsed"] = doc["extensionsRequired"] = {"KHR_materials_diffuse_transmission"};
  check("pointer-required.gltf", doc, "/extensionsRequired/0");
  doc = triangle();
  doc["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
                        {"samplers", {{{"input", 0}, {"output", 0}, {"interpolation", "SMOOTH"}}}}}};
  check("pointer-interpolation.gltf", doc, "/animations/0/samplers/0/interpolation");
}

TEST_CASE("glTF extras: another exporter's light is named in a warning, not dropped without a word",
          "[io][gltf][extras]") {
  Json doc = triangle();
  doc["nodes"][0]["name"] = "Lamp";
  doc["nodes"][0]["extras"] = {{"rt_area_light", {{"size", {1, 1}}, {"power", 100}}},
                               {"lightmap_scale", 2},  // a number: not a light
                               {"notes", {{"light", "no"}}}};
  rt::test::ImportProblems problems;
  REQUIRE(import_gltf(write_gltf("other-light.gltf", square_positions(), doc), std::nullopt, {}, problems));
  REQUIRE(problems.warnings.size() == 1);
  CHECK_THAT(problems.warnings[0], Catch::Contains("node \"Lamp\": extras key \"rt_area_light\" looks like a light, "
                                                   "which rtcli does not read") &&
                                       Catch::Contains("(did you mean \"rtcli_area_light\"?)"));
  const Diagnostic& d = problems.found.all().front();
  CHECK(d.pointer == "/nodes/0/extras/rt_area_light");
  CHECK(d.line > 0);
}
