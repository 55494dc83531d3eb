// schemas/scene.schema.json and the loader must agree: every scene we ship validates, and the
// mistakes the loader rejects for their shape are rejected by the schema too.
#include <filesystem>

#include <catch2/catch.hpp>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validator.hpp>

#include "io/json_document.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

class SchemaChecker {
 public:
  SchemaChecker() {
    const Json schema_json = Json::parse(rt::test::read_file(rt::test::source_path("schemas/scene.schema.json")));
    valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
    parser.populateSchema(valijson::adapters::NlohmannJsonAdapter(schema_json), schema_);
  }
  // Empty when valid, else the validator's first complaint.
  std::string check(const Json& doc) const {
    valijson::Validator validator;
    valijson::ValidationResults results;
    if (validator.validate(schema_, valijson::adapters::NlohmannJsonAdapter(doc), &results)) return "";
    valijson::ValidationResults::Error error;
    results.popError(error);
    std::string where;
    for (const std::string& p : error.context) where += p;
    return where + ": " + error.description;
  }

 private:
  valijson::Schema schema_;
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
      CHECK(schema.check(Json::parse(rt::test::read_file(entry.path().string()))) == "");
      ++checked;
    }
  }
  CHECK(checked >= 3);
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
  CHECK(rejects(j));
  j = base();
  j["nodes"].push_back({{"material", "m"}});  // a material on a group node
  CHECK(rejects(j));
  j = base();
  j.erase("nodes");
  CHECK(rejects(j));
}
