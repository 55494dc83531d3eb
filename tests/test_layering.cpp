// The source tree's layers (README, "Code map"), held by reading every #include: a file may include
// only its own layer and those below it. CMake's link order would catch an upward call, but not an
// upward include of a header-only record; this catches both, and names the file and the line.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tests/support/test_paths.h"

namespace {

// core/'s layers, bottom up (README, "Code map"): the basics at core/'s top (maths, rays,
// transforms, meshes and their placements, the camera); textures, shapes and animation tracks;
// CSG (span lists and the solid the BVH holds); the BVH; the scene's shared assets and settings;
// lights (emissive surfaces are found through the assets); the scene itself, its graph and frames.
// Flattening mesh placements into the top level's triangles sits with the assets it reads.
// Denoisers (images in, an image out) sit on the basics alone.
// The top-level files above the basics are named here one by one.
const std::set<std::string> kCore{"core/",
                                  "core/texture/",
                                  "core/shapes/",
                                  "core/animation/",
                                  "core/csg/",
                                  "core/accel/",
                                  "core/scene_assets",
                                  "core/material",
                                  "core/render_settings.h",
                                  "core/lights/",
                                  "core/scene.",
                                  "core/scene_graph",
                                  "core/csg_template",
                                  "core/frame_scenes",
                                  "core/denoise/",
                                  "core/flatten_instances"};

// `own` and the given layers.
std::set<std::string> with(std::set<std::string> own, const std::set<std::string>& below) {
  own.insert(below.begin(), below.end());
  return own;
}

// Every layer below cli/, and `own`.
std::set<std::string> with_below(std::set<std::string> own) {
  own.insert({"materials/", "core/render/", "io/base/", "io/json/", "io/image/", "io/gltf/", "io/scene/",
              "io/assemble/", "io/"});
  return with(own, kCore);
}

// The layer a source file belongs to: the longest folder prefix in this table.
const std::map<std::string, std::set<std::string>>& allowed_includes() {
  static const std::map<std::string, std::set<std::string>> table{
      {"core/", {"core/"}},
      {"core/texture/", {"core/", "core/texture/"}},
      {"core/shapes/", {"core/", "core/shapes/"}},
      {"core/animation/", {"core/", "core/animation/"}},
      {"core/denoise/", {"core/", "core/denoise/"}},
      {"core/csg/", {"core/", "core/shapes/", "core/csg/"}},
      {"core/accel/", {"core/", "core/texture/", "core/shapes/", "core/csg/", "core/accel/"}},
      {"core/scene_assets",
       {"core/", "core/texture/", "core/shapes/", "core/csg/", "core/accel/", "core/material", "core/scene_assets"}},
      {"core/material", {"core/", "core/texture/", "core/material"}},
      {"core/flatten_instances",
       {"core/", "core/texture/", "core/shapes/", "core/csg/", "core/accel/", "core/material", "core/scene_assets",
        "core/flatten_instances"}},
      {"core/render_settings.h", {"core/", "core/texture/"}},
      {"core/lights/",
       {"core/", "core/texture/", "core/shapes/", "core/csg/", "core/accel/", "core/material", "core/scene_assets",
        "core/lights/"}},
      {"core/scene.", kCore},
      {"core/scene_graph", kCore},
      {"core/csg_template", kCore},
      {"core/frame_scenes", kCore},
      {"materials/", with({"materials/"}, kCore)},
      {"core/render/", with({"materials/", "core/render/"}, kCore)},
      {"io/base/", with({"io/base/"}, kCore)},
      {"io/json/", with({"io/base/", "io/json/"}, kCore)},
      {"io/image/", with({"io/base/", "io/image/"}, kCore)},
      {"io/gltf/", with({"io/base/", "io/json/", "io/image/", "io/gltf/"}, kCore)},
      {"io/scene/", with({"io/base/", "io/json/", "io/image/", "io/scene/"}, kCore)},
      {"io/assemble/", with({"io/base/", "io/json/", "io/image/", "io/gltf/", "io/scene/", "io/assemble/"}, kCore)},
      {"io/", with({"io/base/", "io/json/", "io/image/", "io/gltf/", "io/scene/", "io/assemble/", "io/"}, kCore)},
      // cli/: a folder and a library per job, over everything below (cli/CMakeLists.txt).
      {"cli/common/", with_below({"cli/common/"})},
      {"cli/frames/", with_below({"cli/common/", "cli/frames/"})},
      {"cli/render/", with_below({"cli/common/", "cli/frames/", "cli/render/"})},
      {"cli/farm/", with_below({"cli/common/", "cli/frames/", "cli/farm/"})},
      {"cli/watch/", with_below({"cli/common/", "cli/frames/", "cli/render/", "cli/watch/"})},
      {"cli/bench/", with_below({"cli/common/", "cli/bench/"})},
      {"cli/",
       with_below({"cli/common/", "cli/frames/", "cli/render/", "cli/farm/", "cli/bench/", "cli/watch/", "cli/"})},
  };
  return table;
}

// The table's entry for `file`, or null where the file is above every layer (tools/, tests/).
const std::pair<const std::string, std::set<std::string>>* layer_of(const std::string& file) {
  const std::pair<const std::string, std::set<std::string>>* best = nullptr;
  for (const auto& entry : allowed_includes())
    if (file.rfind(entry.first, 0) == 0 && (!best || entry.first.size() > best->first.size())) best = &entry;
  return best;
}

// The longest layer prefix of an included path: "core/render/film.h" is in core/render/, not core/.
std::string layer_of_include(const std::string& included) {
  std::string best;
  for (const auto& entry : allowed_includes())
    if (included.rfind(entry.first, 0) == 0 && entry.first.size() > best.size()) best = entry.first;
  return best;
}

}  // namespace

TEST_CASE("Every source file includes only its own layer and the layers below it", "[layering]") {
  namespace fs = std::filesystem;
  const std::regex include_line(R"(^\s*#\s*include\s*"([^"]+)\")");
  std::vector<std::string> upward;
  size_t files = 0;
  for (const char* top : {"core", "materials", "io", "cli"}) {
    for (const auto& entry : fs::recursive_directory_iterator(rt::test::source_path(top))) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      const std::string file = fs::relative(entry.path(), rt::test::source_path("")).generic_string();
      const auto* layer = layer_of(file);
      REQUIRE(layer);
      ++files;
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        std::smatch m;
        if (!std::regex_search(line, m, include_line)) continue;
        const std::string included = m[1];
        const std::string target = layer_of_include(included);
        if (target.empty()) continue;  // not one of ours (a generated file, a test helper)
        if (!layer->second.count(target))
          upward.push_back(file + ":" + std::to_string(number) + " (" + layer->first + ") includes " + included);
      }
    }
  }
  INFO("files read: " << files);
  CHECK(files > 200);
  for (const std::string& u : upward) UNSCOPED_INFO(u);
  CHECK(upward.empty());
}

TEST_CASE("The layering check sees an upward include", "[layering]") {
  // The table itself, so that the check above cannot pass by classifying nothing.
  CHECK(layer_of("io/gltf/loader.cpp")->first == "io/gltf/");
  CHECK(layer_of("core/render/renderer.cpp")->first == "core/render/");
  CHECK(layer_of("io/scene_loader.cpp")->first == "io/");
  CHECK(layer_of("cli/main.cpp")->first == "cli/");
  CHECK(layer_of("cli/render/render_plan.cpp")->first == "cli/render/");
  CHECK(layer_of("tools/imagediff/imagediff.cpp") == nullptr);
  CHECK_FALSE(layer_of("cli/frames/frame_output.cpp")->second.count(layer_of_include("cli/render/render_command.h")));
  CHECK_FALSE(layer_of("cli/common/report.cpp")->second.count(layer_of_include("cli/frames/frame_list.h")));
  CHECK(layer_of_include("core/render/film.h") == "core/render/");
  CHECK_FALSE(layer_of("io/image/png_file.cpp")->second.count(layer_of_include("io/json/document.h")));
  CHECK_FALSE(layer_of("core/scene.cpp")->second.count(layer_of_include("materials/phong.h")));
  CHECK_FALSE(layer_of("materials/phong.h")->second.count(layer_of_include("core/render/film.h")));
  // core/'s own: the BVH holds CSG solids, so CSG may not include the BVH (the loop once there).
  CHECK(layer_of("core/csg/csg_object.cpp")->first == "core/csg/");
  CHECK_FALSE(layer_of("core/csg/csg_object.cpp")->second.count(layer_of_include("core/accel/bvh_traversal.h")));
  CHECK(layer_of("core/accel/primitives.h")->second.count(layer_of_include("core/csg/csg_object.h")));
  CHECK(layer_of_include("core/scene_assets.h") == "core/scene_assets");
  CHECK(layer_of_include("core/scene.h") == "core/scene.");
  CHECK_FALSE(layer_of("core/math.h")->second.count(layer_of_include("core/scene.h")));
  CHECK_FALSE(layer_of("core/shapes/sphere.cpp")->second.count(layer_of_include("core/accel/bvh.h")));
}
