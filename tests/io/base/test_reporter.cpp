// The Reporter, the one way a problem travels: places found from pointers (and only so many per
// file, so that a hostile file's many warnings cost linear time), problems inside a referenced
// file reported at the reference, limits that stop loading.
#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "io/base/reporter.h"
#include "io/json/reader.h"

using namespace rt;

TEST_CASE("reporter: a JSON file's pointers get their line:column and a caret", "[io][errors]") {
  Diagnostics diags;
  const auto text = std::make_shared<const std::string>("{\n  \"a\": [1,\n    2]\n}");
  Reporter report(diags, "f.json", json_places(text));
  report.error("/a/1", "expected a string");
  report.warning("/a", "odd", Anchor::kKey);
  REQUIRE(diags.all().size() == 2);
  const Diagnostic& e = diags.all()[0];
  CHECK(e.file == "f.json");
  CHECK(e.pointer == "/a/1");
  CHECK(e.line == 3);
  CHECK(e.column == 5);
  CHECK_THAT(e.excerpt, Catch::Contains("2]"));
  CHECK(diags.all()[1].line == 2);
  CHECK(diags.all()[1].column == 3);  // the key, not the value
  CHECK(report.errors() == 1);
}

TEST_CASE("reporter: only the first problems of a file are placed, so many cost linear time", "[io][errors]") {
  Diagnostics diags;
  size_t scans = 0;
  Reporter report(diags, "many.gltf", [&](const std::string&, Anchor, Place& p) {
    ++scans;
    p.line = 1;
    p.column = 2;
  });
  for (size_t i = 0; i < 1000; ++i) report.warning("/meshes/0/primitives/" + std::to_string(i), "skipped");
  CHECK(scans == Reporter::kPlacesPerFile);
  CHECK(diags.all().size() == 1000);
  CHECK(diags.all()[99].line == 1);
  CHECK(diags.all()[100].line == 0);
  CHECK(diags.all()[100].pointer == "/meshes/0/primitives/100");  // the pointer stays
  // One pointer asked again and again (every problem of a glTF file, at the scene node that
  // places it) is found once.
  Diagnostics again;
  scans = 0;
  Reporter scene(again, "s.json", [&](const std::string&, Anchor, Place& p) {
    ++scans;
    p.line = 7;
  });
  for (int i = 0; i < 500; ++i) scene.place("/nodes/1/mesh/file");
  CHECK(scans == 1);
}

TEST_CASE("reporter: a problem inside a referenced file is reported at the reference", "[io][errors]") {
  Diagnostics scene_diags;
  Reporter scene(scene_diags, "s.json", [](const std::string&, Anchor, Place& p) {
    p.line = 48;
    p.column = 17;
    p.excerpt = "caret";
  });
  Diagnostics inner;
  Reporter model(inner, "m.gltf", [](const std::string&, Anchor, Place& p) {
    p.line = 1;
    p.column = 210;
  });
  model.over_limit("/accessors/0/count", "too many");
  for (const Diagnostic& d : inner.all()) scene.add_inside(d, "/nodes/1/mesh/file", "\"m.gltf\": ");
  REQUIRE(scene_diags.all().size() == 1);
  const Diagnostic& d = scene_diags.all()[0];
  CHECK(d.file == "s.json");
  CHECK(d.line == 48);
  CHECK(d.pointer == "/nodes/1/mesh/file");
  CHECK_THAT(d.message, Catch::StartsWith("\"m.gltf\": too many (a limit that keeps memory bounded"));
  REQUIRE(d.inside);
  CHECK(d.inside->file == "m.gltf");
  CHECK(d.inside->pointer == "/accessors/0/count");
  CHECK(d.inside->column == 210);
  CHECK(model.stopped_by_limit());
  CHECK(format_place(*d.inside) == "  in m.gltf:1:210: /accessors/0/count");

  // A model on its own: its description's pointers are not the user's; the inner place is the place.
  Diagnostics alone_diags;
  Reporter alone(alone_diags, "m.gltf", {}, false);
  alone.error("/nodes/0/mesh", "hidden pointer");
  CHECK(alone_diags.all()[0].pointer.empty());
  alone.add_inside(inner.all()[0], "/nodes/0/mesh/file", "prefix: ");
  const Diagnostic& direct = alone_diags.all()[1];
  CHECK(direct.file == "m.gltf");
  CHECK(direct.pointer == "/accessors/0/count");
  CHECK(direct.column == 210);
  CHECK_FALSE(direct.inside);
}
