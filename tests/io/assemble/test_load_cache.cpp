// The load cache (io/assemble/load_cache.h): a second load of a scene whose files did not change
// reads none of them again; a file that changed (rewritten, or replaced by a rename) is read
// again, and only it. The scene loaded from the cache is the one loaded afresh.
#include <filesystem>
#include <fstream>
#include <thread>

#include <catch2/catch.hpp>

#include "io/assemble/load_cache.h"
#include "tests/support/loading.h"

namespace fs = std::filesystem;

namespace {

std::string cache_scene() {
  return R"({
  "render": {"width": 32, "height": 24},
  "camera": {"position": [0, 1, 6], "look_at": [0, 0, 0]},
  "background": {"environment": "sky.hdr"},
  "materials": {"bricks": {"texture": "bricks.png"}, "grey": {"kd": 0.5}},
  "lights": [{"type": "point", "position": [2, 4, 3]}],
  "nodes": [
    {"shape": "cube", "material": "bricks"},
    {"mesh": {"file": "knot.glb"}, "transform": {"translate": [2, 0, 0]}},
    {"mesh": {"file": "gem.gltf"}, "transform": {"translate": [-2, 0, 0]}}
  ]
})";
}

// Loads with the cache; the counts it took.
rt::LoadCache::Counts load_with(rt::LoadCache& cache, const std::string& path, rt::LoadedScene* out = nullptr) {
  rt::LoadOptions options = rt::test::load_options();
  options.cache = &cache;
  rt::Diagnostics diags;
  auto loaded = rt::load_scene(path, options, diags);
  for (const rt::Diagnostic& d : diags.all()) UNSCOPED_INFO(rt::format_diagnostic(d));
  REQUIRE(loaded);
  if (out) *out = std::move(*loaded);
  return cache.take_counts();
}

}  // namespace

TEST_CASE("load cache: what did not change is kept, what changed is read again", "[io][cache]") {
  const std::string dir = rt::test::fresh_folder("load-cache");
  for (const char* f : {"models/knot.glb", "models/gem.gltf", "models/gem.bin", "textures/bricks.png",
                        "textures/sky.hdr", "textures/checker.png"})
    fs::copy_file(rt::test::source_path(std::string("scenes/") + f), dir + "/" + fs::path(f).filename().string());
  const std::string scene = dir + "/scene.json";
  std::ofstream(scene) << cache_scene();

  rt::LoadCache cache;
  rt::LoadedScene first;
  auto counts = load_with(cache, scene, &first);
  CHECK(counts.read == 4);  // two models, a texture, an environment image
  CHECK(counts.kept == 0);

  // The scene file alone changed: everything it reads is kept.
  std::ofstream(scene) << cache_scene() << "\n";
  rt::LoadedScene second;
  counts = load_with(cache, scene, &second);
  CHECK(counts.read == 0);
  CHECK(counts.kept == 4);
  // The same scene: the same meshes, BVHs and textures.
  REQUIRE(second.scene.assets->meshes.size() == first.scene.assets->meshes.size());
  for (size_t i = 0; i < first.scene.assets->meshes.size(); ++i) {
    CHECK(second.scene.assets->meshes[i].mesh.positions == first.scene.assets->meshes[i].mesh.positions);
    CHECK(second.scene.assets->meshes[i].bvh.nodes().size() == first.scene.assets->meshes[i].bvh.nodes().size());
  }
  CHECK(second.scene.assets->textures.size() == first.scene.assets->textures.size());
  CHECK(second.inputs == first.inputs);

  // The texture replaced by a rename (another image): it alone is read again.
  fs::copy_file(dir + "/checker.png", dir + "/bricks.new.png");
  fs::rename(dir + "/bricks.new.png", dir + "/bricks.png");
  counts = load_with(cache, scene);
  CHECK(counts.read == 1);
  CHECK(counts.kept == 3);

  // A model's buffer rewritten in place (same size, later time): that model alone.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const std::string bin = rt::test::read_file(dir + "/gem.bin");
  std::ofstream(dir + "/gem.bin", std::ios::binary) << bin;
  counts = load_with(cache, scene);
  CHECK(counts.read == 1);
  CHECK(counts.kept == 3);
}
