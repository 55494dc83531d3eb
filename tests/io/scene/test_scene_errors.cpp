// Every class of bad scene input is rejected with the file, the JSON pointer, what was expected
// and what was found; loading never throws or crashes.
#include <catch2/catch.hpp>

#include "io/json/document.h"
#include "io/scene_loader.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;
using rt::test::write_file;

namespace {

// A small valid scene; each case breaks one thing in it.
Json valid_scene() {
  return Json::parse(R"({
    "render": {"width": 32, "height": 24},
    "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], "fov": 45},
    "materials": {"red": {"kd": [0.8, 0.1, 0.1], "ks": 0.2, "shininess": 20}},
    "lights": [{"type": "point", "position": [2, 4, 3]}],
    "nodes": [{"name": "ball", "shape": "sphere", "material": "red"}]
  })");
}

struct Attempt {
  bool loaded = false;
  Diagnostics diags;
  const Diagnostic& first() const { return diags.all().front(); }
};

Attempt load_path(const std::string& path) {
  Attempt a;
  a.loaded = load_scene(path, rt::test::load_options(), a.diags).has_value();
  return a;
}

Attempt load_text(const std::string& name, const std::string& text) { return load_path(write_file(name, text)); }
Attempt load_json(const std::string& name, const Json& j) { return load_text(name, j.dump(2)); }

// The one-line message a user sees, for checks on its wording.
std::string line(const Attempt& a) { return format_diagnostic(a.first()); }

}  // namespace

TEST_CASE("the valid base scene loads", "[io][errors]") {
  const Attempt a = load_json("valid.json", valid_scene());
  CHECK(a.loaded);
  CHECK_FALSE(a.diags.has_errors());
}

TEST_CASE("missing and unreadable files", "[io][errors]") {
  Attempt a = load_path(rt::test::output_path("does-not-exist.json"));
  REQUIRE_FALSE(a.loaded);
  CHECK_THAT(line(a), Catch::Contains("does-not-exist.json: error: file not found"));
  a = load_path(rt::test::output_path(""));  // a folder
  REQUIRE_FALSE(a.loaded);
  CHECK_THAT(line(a), Catch::Contains("is a directory"));
}

TEST_CASE("JSON syntax errors report line:column and where in the tree", "[io][errors]") {
  const Attempt a = load_text("syntax.json", "{\n  \"camera\": {\n    \"position\": [0, 0, 5],\n  }\n}\n");
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().line == 4);
  CHECK(a.first().column == 3);
  CHECK(a.first().pointer == "/camera/position");
  CHECK_THAT(a.first().message, Catch::StartsWith("invalid JSON: syntax error while parsing object key"));
  CHECK_THAT(a.first().excerpt, Catch::Contains("^"));
  CHECK_FALSE(load_text("empty.json", "").loaded);
  CHECK_FALSE(load_text("truncated.json", "{\"camera\": {").loaded);
  CHECK_FALSE(load_text("bad-utf8.json", "{\"camera\": \"\xff\"}").loaded);
}

TEST_CASE("wrong types name the pointer, the expected type and the value found", "[io][errors]") {
  Json j = valid_scene();
  j["camera"]["fov"] = "wide";
  const Attempt a = load_json("wrong-type.json", j);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/camera/fov");
  CHECK(a.first().message == "expected a number in (0, 180), found the string \"wide\"");
  CHECK_THAT(a.first().excerpt, Catch::Contains("\"fov\": \"wide\""));  // the line shown is the value's
  CHECK(a.first().line > 1);
  j = valid_scene();
  j["materials"]["red"]["kd"] = {1, "x", 0};
  const Attempt b = load_json("wrong-element.json", j);
  REQUIRE_FALSE(b.loaded);
  CHECK(b.first().pointer == "/materials/red/kd/1");
  CHECK(b.first().message == "expected a number >= 0, found the string \"x\"");
  j = valid_scene();
  j["nodes"] = Json::object();
  CHECK_THAT(line(load_json("nodes-object.json", j)),
             Catch::Contains("/nodes: expected an array of nodes, found an empty object"));
}

TEST_CASE("missing required keys", "[io][errors]") {
  Json j = valid_scene();
  j["camera"].erase("look_at");
  const Attempt a = load_json("missing-key.json", j);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/camera/look_at");
  CHECK(a.first().message == "missing required key \"look_at\"; expected an array of 3 numbers [x, y, z]");
  j = valid_scene();
  j["nodes"][0].erase("material");
  CHECK(load_json("missing-material.json", j).first().pointer == "/nodes/0/material");
  j = valid_scene();
  j.erase("camera");
  CHECK(load_json("missing-camera.json", j).first().pointer == "/camera");
}

TEST_CASE("unknown keys are errors with a suggestion", "[io][errors]") {
  Json j = valid_scene();
  j["materials"]["red"]["shinyness"] = 3;
  const Attempt a = load_json("unknown-key.json", j);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/materials/red/shinyness");
  CHECK_THAT(a.first().message, Catch::StartsWith("unknown key \"shinyness\" (did you mean \"shininess\"?)"));
  j = valid_scene();
  j["lights"][0]["colour"] = {1, 1, 1};
  CHECK_THAT(load_json("colour.json", j).first().message, Catch::Contains("did you mean \"color\"?"));
}

TEST_CASE("undefined names and bad enum values list the valid ones", "[io][errors]") {
  Json j = valid_scene();
  j["nodes"][0]["material"] = "rde";
  Attempt a = load_json("undefined-material.json", j);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/nodes/0/material");
  CHECK_THAT(a.first().message, Catch::Contains("(\"red\")") && Catch::Contains("found the undefined name \"rde\"") &&
                                    Catch::Contains("did you mean \"red\"?"));
  j = valid_scene();
  j["nodes"][0]["shape"] = "cylindre";
  a = load_json("bad-shape.json", j);
  CHECK(a.first().pointer == "/nodes/0/shape");
  CHECK_THAT(a.first().message, Catch::Contains("\"cone\"") && Catch::Contains("did you mean \"cylinder\"?"));
}

TEST_CASE("unreadable glTF files", "[io][errors][gltf]") {
  Json j = valid_scene();
  j["nodes"][0] = {{"mesh", {{"file", "missing.glb"}}}};
  Attempt a = load_json("missing-gltf.json", j);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/nodes/0/mesh/file");
  CHECK_THAT(a.first().message,
             Catch::Contains("expected a readable glTF 2.0 file") && Catch::Contains("file not found"));
  const char garbage[] = "glTF\x02\0\0\0\xff\xff\xff\x7fnot really";  // a header announcing 2 GiB
  write_file("garbage.glb", std::string(garbage, sizeof garbage - 1));
  write_file(
      "garbage.gltf",
      "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 7}}]}]}");
  for (const char* file : {"garbage.glb", "garbage.gltf"}) {
    j["nodes"][0]["mesh"]["file"] = file;
    a = load_json("corrupt-gltf.json", j);
    REQUIRE_FALSE(a.loaded);
    CHECK(a.first().pointer == "/nodes/0/mesh/file");
  }
}

TEST_CASE("numbers that are not finite in single or double precision", "[io][errors]") {
  const std::string text = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 1e999}, "nodes": []})";
  const Attempt a = load_text("overflow.json", text);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/camera/fov");
  CHECK(a.first().message == "expected a finite number, found 1e999 (too large for a double)");
  CHECK(a.first().column == text.find("1e999") + 1);
  Json j = valid_scene();
  j["camera"]["position"] = {0, 1e300, 5};
  CHECK_THAT(load_json("float-overflow.json", j).first().message, Catch::Contains("single precision"));
}

TEST_CASE("zero and negative sizes", "[io][errors]") {
  Json j = valid_scene();
  j["render"]["width"] = 0;
  Attempt a = load_json("zero-width.json", j);
  CHECK(a.first().pointer == "/render/width");
  CHECK(a.first().message == "expected an integer in [1, 16384], found the number 0");
  j = valid_scene();
  j["materials"]["red"]["shininess"] = -1;
  CHECK(load_json("negative-shininess.json", j).first().message == "expected a number > 0, found the number -1");
  j = valid_scene();
  j["nodes"][0]["transform"] = {{"scale", {1, 0, 1}}};
  a = load_json("zero-scale.json", j);
  CHECK(a.first().pointer == "/nodes/0/transform/scale");
  CHECK_THAT(a.first().message, Catch::StartsWith("expected non-zero scale factors"));
  j = valid_scene();
  j["lights"][0]["attenuation"] = {0, 0, 0};
  CHECK(load_json("zero-attenuation.json", j).first().pointer == "/lights/0/attenuation");
  j = valid_scene();
  j["render"]["width"] = 2.5;
  CHECK(load_json("fractional-width.json", j).first().pointer == "/render/width");
}

TEST_CASE("singular transforms", "[io][errors]") {
  Json j = valid_scene();
  j["nodes"][0]["transform"] = {{"matrix", {{1, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}};
  Attempt a = load_json("singular-matrix.json", j);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/nodes/0/transform/matrix");
  CHECK_THAT(a.first().message, Catch::StartsWith("expected an invertible matrix, found a singular one"));
  j = valid_scene();
  j["nodes"][0]["transform"] = {{"matrix", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 1, 1}}}};
  CHECK(load_json("projective.json", j).first().pointer == "/nodes/0/transform/matrix/3");
  j = valid_scene();
  j["nodes"][0]["transform"] = {{"matrix", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}, {"scale", 2}};
  CHECK(load_json("matrix-and-scale.json", j).first().pointer == "/nodes/0/transform/scale");
}

TEST_CASE("camera that cannot look anywhere", "[io][errors]") {
  Json j = valid_scene();
  j["camera"]["look_at"] = {0, 1, 5};
  CHECK(load_json("look-at-self.json", j).first().pointer == "/camera/look_at");
  j = valid_scene();
  j["camera"]["position"] = {0, 5, 0};
  j["camera"]["up"] = {0, 2, 0};
  CHECK(load_json("up-parallel.json", j).first().pointer == "/camera/up");
}

TEST_CASE("duplicate keys and duplicate node names", "[io][errors]") {
  const std::string text =
      R"({"camera": {"position": [0,0,5], "look_at": [0,0,0], "fov": 30, "fov": 40}, "nodes": []})";
  Attempt a = load_text("duplicate-key.json", text);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/camera/fov");
  CHECK(a.first().column == text.rfind("\"fov\"") + 1);  // the second "fov"
  Json j = valid_scene();
  j["nodes"].push_back(j["nodes"][0]);
  a = load_json("duplicate-name.json", j);
  CHECK(a.first().pointer == "/nodes/1/name");
  CHECK_THAT(a.first().message, Catch::Contains("already used by /nodes/0"));
}

TEST_CASE("every error in a file is reported, not just the first", "[io][errors]") {
  Json j = valid_scene();
  j["render"]["height"] = -3;
  j["materials"]["red"]["ks"] = "shiny";
  j["nodes"][0]["material"] = "blue";
  const Attempt a = load_json("three-errors.json", j);
  REQUIRE_FALSE(a.loaded);
  CHECK(a.diags.error_count() == 3);
}

TEST_CASE("absurdly deep nesting is refused, not a stack overflow", "[io][errors]") {
  const std::string deep = "{\"nodes\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  const Attempt a = load_text("deep.json", deep);
  REQUIRE_FALSE(a.loaded);
  CHECK_THAT(a.first().message, Catch::Contains("nested at most 512 levels"));
}

TEST_CASE("binary files and bytes that are not text never reach the terminal raw", "[io][errors]") {
  Attempt a = load_text("binary.json", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().message == "expected a JSON scene, found binary data");
  a = load_text("glb.json", std::string("glTF\x02\0\0\0", 8));
  CHECK_THAT(a.first().message, Catch::Contains("name it .glb"));
  a = load_text("bad-bytes.json",
                "{\"camera\": {\"fov\": \"\x01"
                "caf\xc3\xa9\xff\"}}");
  REQUIRE_FALSE(a.loaded);
  for (const Diagnostic& d : a.diags.all())
    for (const char c : d.message + d.excerpt) CHECK((static_cast<unsigned char>(c) >= 0x20 || c == '\n' || c == '\t'));
  CHECK(printable("caf\xc3\xa9 \xff\x1b[2J") == "caf\xc3\xa9 ??[2J");
}

TEST_CASE("minified files get a windowed excerpt around the error", "[io][errors]") {
  Json j = valid_scene();
  j["camera"]["fov"] = "wide";
  const Attempt a = load_text("minified.json", j.dump() + std::string(500, ' '));
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().line == 1);
  CHECK(a.first().excerpt.size() < 300);
}

TEST_CASE("scene files may hold // and /* */ comments, positions and pointers stay right", "[io][errors]") {
  // Brackets, quotes and "//" inside comments and strings must not confuse the scans that find
  // positions and count nesting.
  const std::string head = R"(// A commented scene: "quotes" and {braces} in a comment.
{
  /* the render block, with a [bracket]
     over two lines */
  "render": {"width": 32, "height": 24},  // trailing comment
  "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], /* inline */ "fov": 45},
  "materials": {"red": {"kd": [0.8, 0.1, 0.1], "texture_note_free": 1}},
)";
  const std::string tail = R"(
  "lights": [{"type": "point", "position": [2, 4, 3]}],
  "nodes": [{"name": "http://a//b", "shape": "sphere", "material": "red"}]  /* last */
}
// the end)";
  // The unknown key is reported at its own line and column, past the comments.
  Attempt bad = load_text("comments_bad.json", head + tail);
  REQUIRE_FALSE(bad.loaded);
  CHECK(bad.first().pointer == "/materials/red/texture_note_free");
  CHECK(bad.first().line == 7);
  CHECK(bad.first().column == 48);
  // Fixed, it loads; the node's name keeps its "//".
  std::string good = head;
  good.replace(good.find(", \"texture_note_free\": 1"), std::string(", \"texture_note_free\": 1").size(), "");
  const LoadedScene s = rt::test::load_scene_text("comments_good.json", good + tail);
  CHECK(s.scene.bvh.primitive_count() == 1);
  // An unclosed comment is a syntax error at the end, not a hang or a crash.
  CHECK_FALSE(load_text("comments_open.json", "{\"render\": {} /* never closed").loaded);
}

TEST_CASE("the nesting scan skips comments", "[io][errors]") {
  CHECK(json_nesting_within("[ // [[[[\n 1 /* [[[[ */ ]", 1));
  CHECK_FALSE(json_nesting_within("[[ /* ] */ ]]", 1));
  CHECK(json_nesting_within("[\"/* [[[ */\"]", 1));
}

TEST_CASE("texture mappings: wrap per axis and the projection axis", "[io][uv]") {
  const std::string folder = rt::test::source_path("scenes/textures/");
  const auto scene_with = [&](const std::string& mapping) {
    return R"({
      "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], "fov": 45},
      "materials": {"label": {"texture": {"file": ")" +
           folder + R"(checker.png", )" + mapping + R"(}}},
      "lights": [{"type": "point", "position": [2, 4, 3]}],
      "nodes": [{"name": "can", "shape": "cylinder", "material": "label"}]
    })";
  };
  const LoadedScene s = rt::test::load_scene_text(
      "mapping_axes.json", scene_with(R"("projection": "cylindrical", "axis": "x", "wrap": ["repeat", "clamp"])"));
  const TextureMapping& m = s.scene.materials().at(0).texture.mapping;
  CHECK(m.axis == ProjectionAxis::kX);
  CHECK(m.wrap == WrapModes(TextureWrap::kRepeat, TextureWrap::kClamp));
  CHECK(rt::test::load_scene_text("mapping_one.json", scene_with(R"("wrap": "mirror")"))
            .scene.materials()
            .at(0)
            .texture.mapping.wrap == WrapModes(TextureWrap::kMirror));

  Attempt a = load_text("mapping_bad_wrap.json", scene_with(R"("wrap": ["repeat"])"));
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/materials/label/texture/wrap");
  CHECK_THAT(a.first().message, Catch::Contains("or an array of 2, [u, v]"));
  a = load_text("mapping_bad_wrap_v.json", scene_with(R"("wrap": ["repeat", "clmap"])"));
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/materials/label/texture/wrap/1");
  CHECK_THAT(a.first().message, Catch::Contains("did you mean \"clamp\""));
  a = load_text("mapping_bad_axis.json", scene_with(R"("axis": "w")"));
  REQUIRE_FALSE(a.loaded);
  CHECK(a.first().pointer == "/materials/label/texture/axis");
}
