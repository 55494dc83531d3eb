// The bad-scene corpus (tests/data/bad/): one file per class of error. Each is rejected by the
// loader (what `rtcli render` runs) and by the validator (`rtcli validate`) with its expected
// JSON pointer and message, and, where a JSON Schema can express the rule, by the schema alone.
// Every shipped scene passes all three (tests/io/scene/test_schema.cpp and below).
#include <filesystem>

#include <catch2/catch.hpp>

#include "io/json/document.h"
#include "io/json/locate.h"
#include "io/scene/schema.h"
#include "io/scene_loader.h"
#include "io/scene_validator.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

// Whether some error sits at `pointer` with `message` in its text, and, for a problem inside a
// glTF file the scene names, at `inside` there (its pointer, line and column, with an excerpt).
bool reports(const Diagnostics& diags, const std::string& pointer, const std::string& message,
             const Json& inside = Json()) {
  for (const Diagnostic& d : diags.all()) {
    if (d.severity != Severity::kError || d.pointer != pointer || d.message.find(message) == std::string::npos)
      continue;
    if (inside.is_null()) return true;
    if (d.inside && d.inside->pointer == inside["pointer"] && d.inside->line == inside["line"] &&
        d.inside->column == inside["column"] && !d.inside->excerpt.empty())
      return true;
  }
  return false;
}

std::string all_messages(const Diagnostics& diags) {
  std::string out;
  for (const Diagnostic& d : diags.all()) out += format_diagnostic(d) + "\n";
  return out;
}

}  // namespace

TEST_CASE("bad scenes: every one is rejected by the loader, the validator and (where it can) the schema",
          "[io][errors][schema]") {
  const std::string folder = rt::test::source_path("tests/data/bad/");
  const Json expected = Json::parse(rt::test::read_file(folder + "expected.json"));
  size_t files = 0, schema_cases = 0, inside_cases = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".json" && entry.path().filename() != "expected.json") ++files;
  CHECK(files == expected.size());  // every file has an expectation, and every expectation a file
  CHECK(expected.size() >= 40);
  for (const auto& item : expected.items()) {
    const std::string path = folder + item.key();
    const std::string pointer = item.value()["pointer"], message = item.value()["message"];
    const Json inside = item.value().value("inside", Json());
    inside_cases += inside.is_null() ? 0 : 1;
    INFO(item.key() << ": expected " << pointer << ": ..." << message << "...");

    Diagnostics load_diags;
    CHECK_FALSE(load_scene(path, rt::test::load_options(), load_diags));
    INFO("loader said:\n" << all_messages(load_diags));
    CHECK(reports(load_diags, pointer, message, inside));

    const Diagnostics validate_diags = validate_file(path, rt::test::load_options());
    INFO("validator said:\n" << all_messages(validate_diags));
    CHECK(validate_diags.has_errors());
    CHECK(reports(validate_diags, pointer, message, inside));
    // One code path: the same problems, in the same order, whichever command asks.
    CHECK(all_messages(load_diags) == all_messages(validate_diags));

    if (item.value()["schema"] == true) {
      ++schema_cases;
      const auto errors = check_scene_schema(Json::parse(rt::test::read_file(path)));
      std::string said;
      bool found = false;
      for (const SchemaError& e : errors) {
        said += e.pointer + ": " + e.message + "\n";
        found = found || pointers_related(e.pointer, pointer);
      }
      INFO("schema said:\n" << said);
      CHECK(found);
    }
  }
  CHECK(schema_cases >= 40);
  CHECK(inside_cases >= 6);  // problems inside glTF files, at their pointer and line:column

  // The documentation's counts are the corpus's.
  const std::string testing = rt::test::read_file(rt::test::source_path("docs/testing.md"));
  const std::string limits = rt::test::read_file(rt::test::source_path("docs/errors-and-limits.md"));
  CHECK_THAT(testing, Catch::Contains("(`tests/data/bad/`, " + std::to_string(files) + " files,"));
  CHECK_THAT(testing, Catch::Contains("where JSON Schema can say it (" + std::to_string(schema_cases) + " of them)"));
  CHECK_THAT(limits, Catch::Contains("one scene per class of error (" + std::to_string(files) + " of them)"));
}

TEST_CASE("validator: every shipped scene and model is valid, with no schema complaint and no warning",
          "[io][schema]") {
  int checked = 0;
  for (const char* folder : {"scenes", "scenes/models", "scenes/toys", "scenes/gallery", "tests/data"}) {
    for (const auto& entry : std::filesystem::directory_iterator(rt::test::source_path(folder))) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".json" && ext != ".glb" && ext != ".gltf") continue;
      const Diagnostics diags = validate_file(entry.path().string(), rt::test::load_options());
      INFO(entry.path().string() << "\n" << all_messages(diags));
      CHECK(diags.all().empty());  // not even a warning (a rect light facing away, say)
      ++checked;
    }
  }
  CHECK(checked >= 5);
}

TEST_CASE("validator: reports problems the loader stops before (bad values and a missing model)", "[io][errors]") {
  const std::string path = rt::test::write_file("two-kinds.json", R"({
    "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], "fov": "wide"},
    "materials": {"m": {}},
    "nodes": [{"mesh": {"file": "nowhere.glb"}}]
  })");
  const Diagnostics diags = validate_file(path, rt::test::load_options());
  CHECK(reports(diags, "/camera/fov", "expected a number"));
  CHECK(reports(diags, "/nodes/0/mesh/file", "file not found"));
  CHECK(diags.error_count() == 2);
}
