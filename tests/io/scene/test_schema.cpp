// schemas/scene.schema.json and the loader must agree: every scene we ship validates, and the
// mistakes the loader rejects for their shape are rejected by the schema too.
#include <algorithm>
#include <filesystem>

#include <catch2/catch.hpp>

#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "io/json/document.h"
#include "io/scene/schema.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

// The io layer's schema check (the schema compiled into the binary); empty when valid, else the
// first complaint.
class SchemaChecker {
 public:
  std::string check(const Json& doc) const {
    const auto errors = check_scene_schema(doc);
    return errors.empty() ? "" : errors.front().pointer + ": " + errors.front().message;
  }
};

Json base() {
  return Json::parse(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
                         "materials": {"m": {"kd": 0.5}},
                         "nodes": [{"shape": "sphere", "material": "m"}]})");
}

}  // namespace

TEST_CASE("schema: every shipped scene validates", "[schema]") {
  const SchemaChecker schema;
  int checked = 0;
  for (const char* folder : {"scenes", "tests/data"}) {
    for (const auto& entry : std::filesystem::directory_iterator(rt::test::source_path(folder))) {
      if (entry.path().extension() != ".json") continue;
      INFO(entry.path().string());
      // Scene files may hold comments, which a schema tool for plain JSON would need stripped.
      CHECK(schema.check(Json::parse(rt::test::read_file(entry.path().string()), nullptr, true, true)) == "");
      ++checked;
    }
  }
  CHECK(checked >= 3);
  // Included files (scenes/library/) hold part of a scene: with a camera and nodes added, a scene.
  int parts = 0;
  for (const auto& entry : std::filesystem::directory_iterator(rt::test::source_path("scenes/library"))) {
    INFO(entry.path().string());
    Json part = Json::parse(rt::test::read_file(entry.path().string()), nullptr, true, true);
    if (!part.contains("camera")) part["camera"] = base()["camera"];
    if (!part.contains("nodes")) part["nodes"] = Json::array();
    const std::string problems = schema.check(part);
    // A template's shape may leave its material to where it is placed; JSON Schema cannot know.
    CHECK((problems == "" || problems.find("/templates/") != std::string::npos));
    ++parts;
  }
  CHECK(parts >= 2);
  CHECK(schema.check(base()) == "");
}

TEST_CASE("schema: rejects what the loader rejects for its shape", "[schema]") {
  const SchemaChecker schema;
  const auto rejects = [&](const Json& doc) { return !schema.check(doc).empty(); };
  Json j = base();
  j["camera"]["fov"] = "wide";
  CHECK(rejects(j));
  j = base();
  j["materials"]["m"]["shinyness"] = 3;
  CHECK(rejects(j));
  j = base();
  j["nodes"][0].erase("material");
  CHECK(rejects(j));
  j = base();
  j["nodes"][0]["mesh"] = {{"file", "a.glb"}};
  CHECK(rejects(j));  // shape and mesh together
  j = base();
  j["nodes"][0]["transform"] = {{"matrix", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}, {"scale", 2}};
  CHECK(rejects(j));
  j["nodes"][0]["transform"].erase("scale");
  CHECK_FALSE(rejects(j));
  j["nodes"][0]["transform"]["matrix"][3] = {0, 0, 1, 1};
  CHECK(rejects(j));
  j = base();
  j["nodes"][0]["transform"] = {{"scale", {1, 0, 1}}};
  CHECK(rejects(j));
  j = base();
  j["render"] = {{"width", 0}};
  CHECK(rejects(j));
  j = base();
  j["lights"] = {{{"type", "spot"}, {"position", {0, 1, 0}}}};
  CHECK(rejects(j));  // no direction
  j["lights"][0]["direction"] = {0, -1, 0};
  CHECK_FALSE(rejects(j));
  j["lights"][0]["outer_angle"] = 120;
  CHECK(rejects(j));
  j["lights"] = {{{"type", "directional"}, {"direction", {0, 0, 0}}}};
  CHECK(rejects(j));
  j["lights"][0]["direction"] = {1, -1, 0};
  CHECK_FALSE(rejects(j));
  j["lights"] = {{{"type", "laser"}, {"position", {0, 1, 0}}}};
  CHECK(rejects(j));
  j = base();
  j["nodes"].push_back({{"mesh", {{"file", "a.glb"}, {"materials", {{"Bottle", "m"}}}}}});
  CHECK_FALSE(rejects(j));
  j["nodes"].back()["mesh"]["materials"]["Cap"] = 3;
  CHECK(rejects(j));
  j = base();
  j["nodes"].push_back({{"material", "m"}});  // a material on a group node
  CHECK(rejects(j));
  j = base();
  j.erase("nodes");
  CHECK(rejects(j));
}

TEST_CASE("schema: the copy compiled into the binary is schemas/scene.schema.json", "[schema]") {
  CHECK(scene_schema_text() == rt::test::read_file(rt::test::source_path("schemas/scene.schema.json")));
}

TEST_CASE("schema: every enum of names is the code's name table", "[schema]") {
  // The schema is written by hand; the names come from the code's name tables (core/name_table.h).
  // A new integrator, sampler, curve or mode must be added to both, or `validate` would refuse a
  // scene that renders.
  const Json schema = Json::parse(rt::test::read_file(rt::test::source_path("schemas/scene.schema.json")));
  const auto sorted = [](std::vector<std::string> names) {
    std::sort(names.begin(), names.end());
    return names;
  };
  const auto names_at = [&](const char* pointer) {
    return sorted(schema.at(Json::json_pointer(pointer)).get<std::vector<std::string>>());
  };
  CHECK(names_at("/definitions/render/properties/integrator/enum") == sorted(integrators().names()));
  CHECK(names_at("/definitions/render/properties/antialias/properties/mode/enum") == sorted(pixel_samplers().names()));
  CHECK(names_at("/definitions/render/properties/antialias/properties/positions/enum") ==
        sorted(kSamplePositions.names()));
  CHECK(names_at("/definitions/render/properties/tone_map/enum") == sorted(kToneMaps.names()));
  CHECK(names_at("/definitions/render/properties/secondary_shadows/enum") == sorted(kSecondaryShadows.names()));
  CHECK(names_at("/definitions/render/properties/sampler/enum") == sorted(kSampleSequences.names()));
  std::vector<std::string> layouts = kStereoModes.names();
  layouts.erase(layouts.begin());  // a camera's stereo block names a layout: "none" is leaving it out
  CHECK(names_at("/definitions/camera/properties/stereo/properties/mode/enum") == sorted(layouts));
  for (const char* slot : {"texture", "bump", "normal_map"})
    CHECK(names_at(("/definitions/" + std::string(slot) + "/oneOf/1/properties/filter/enum").c_str()) ==
          sorted(kTextureFilters.names()));
}
